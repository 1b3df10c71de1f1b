#include "Plane.h"

#include "Clean.h" // formatNumber
#include "NumberText.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

namespace osm
{

namespace
{

double dot(const Vec3& a, const Vec3& b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

Vec3 cross(const Vec3& a, const Vec3& b)
{
  return { a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x };
}

Vec3 sub(const Vec3& a, const Vec3& b)
{
  return { a.x - b.x, a.y - b.y, a.z - b.z };
}

Vec3 scaled(const Vec3& a, double s)
{
  return { a.x * s, a.y * s, a.z * s };
}

Vec3 normalized(const Vec3& a)
{
  // Rescale first so that squaring can neither overflow nor underflow.
  const double m = std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(a.z) });
  if (m == 0)
    return a;
  const Vec3 b = scaled(a, 1.0 / m);
  return scaled(b, 1.0 / std::sqrt(dot(b, b)));
}

double component(const Vec3& a, int k)
{
  return k == 0 ? a.x : (k == 1 ? a.y : a.z);
}

Vec3 axis(int k)
{
  return { k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0 };
}

using Matrix3 = std::array<std::array<double, 3>, 3>;

/// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations.
/// On return the diagonal of a holds the eigenvalues, column k of vectors the
/// eigenvector of a[k][k].
void jacobi(Matrix3& a, Matrix3& vectors)
{
  vectors = { { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  for (int sweep = 0; sweep < 64; ++sweep)
  {
    const double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
    const double diag = std::fabs(a[0][0]) + std::fabs(a[1][1]) + std::fabs(a[2][2]);
    if (off == 0 || off <= 1e-300 || off <= 1e-18 * diag)
      return;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q)
      {
        if (a[p][q] == 0)
          continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) /
          (std::fabs(theta) + std::sqrt(theta * theta + 1)); // tan of the rotation
        const double c = 1 / std::sqrt(t * t + 1);
        const double s = t * c;
        for (int k = 0; k < 3; ++k) // columns p and q of a
        {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) // rows p and q of a
        {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        a[p][q] = a[q][p] = 0; // exact zero, not rounding noise
        for (int k = 0; k < 3; ++k)
        {
          const double vkp = vectors[k][p], vkq = vectors[k][q];
          vectors[k][p] = c * vkp - s * vkq;
          vectors[k][q] = s * vkp + c * vkq;
        }
      }
  }
}

/// The frame for a normal: orient it, then pick u and v. A normal whose z is
/// at most vertical counts as horizontal (the plane as vertical).
PlaneFrame frameFor(const Vec3& origin, Vec3 n, double vertical = 1e-9)
{
  n = normalized(n);
  int smallest = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::fabs(component(n, k)) < std::fabs(component(n, smallest)))
      smallest = k;
  }
  // Up, so that triangles turn counter-clockwise seen from +z as a z = c
  // plane's do (a review: by the largest component, planes just either side
  // of 45 degrees came out turned opposite ways); a vertical plane's, whose
  // z is rounding, from +y, or +x.
  const int up = std::fabs(n.z) > vertical ? 2 : std::fabs(n.y) > vertical ? 1 : 0;
  if (component(n, up) < 0)
    n = scaled(n, -1.0);
  PlaneFrame f;
  f.origin = origin;
  f.normal = n;
  f.vertical = vertical;
  const Vec3 e = axis(smallest);
  f.u = normalized(sub(e, scaled(n, component(n, smallest))));
  f.v = cross(n, f.u);
  return f;
}

/// Whether the points' (x, y) lie on one line (or are all one point), within
/// the plane fit's tolerance (relativeTolerance of their extent) and the
/// rounding of their coordinates (roundoff of the largest, as stored).
bool xyOnOneLine(const Array<Vec3>& points, double relativeTolerance, double roundoff)
{
  if (points.empty())
    return true;
  const auto xy = [](const Vec3& p) { return Point{ p.x, p.y }; };
  Bounds box{ xy(points.front()), xy(points.front()) };
  double largest = 0.0;
  for (const Vec3& p : points)
  {
    extend(box, xy(p));
    largest = std::max({ largest, std::fabs(p.x), std::fabs(p.y) });
  }
  // The line through the extreme points along the wider side.
  const bool alongX = box.width() >= box.height();
  const auto byAxis = [alongX](
                        const Vec3& p, const Vec3& q) { return alongX ? p.x < q.x : p.y < q.y; };
  const Point a = xy(*std::min_element(points.begin(), points.end(), byAxis));
  const Point b = xy(*std::max_element(points.begin(), points.end(), byAxis));
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  if (length == 0)
    return true;
  const double tolerance =
    relativeTolerance * std::hypot(box.width(), box.height()) + 4 * roundoff * largest;
  return std::all_of(points.begin(), points.end(), [&](const Vec3& p) {
    return std::fabs((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)) / length <= tolerance;
  });
}

} // namespace

Point PlaneFrame::toPlane(const Vec3& p) const
{
  const Vec3 d = sub(p, origin);
  return { dot(d, u), dot(d, v) };
}

Vec3 PlaneFrame::fromPlane(const Point& q) const
{
  return { origin.x + q.x * u.x + q.y * v.x, origin.y + q.x * u.y + q.y * v.y,
    origin.z + q.x * u.z + q.y * v.z };
}

double PlaneFrame::distance(const Vec3& p) const
{
  return dot(sub(p, origin), normal);
}

Point PlaneFrame::liftXY(double x, double y) const
{
  if (std::fabs(normal.z) <= vertical)
    return toPlane({ x, y, origin.z });
  const double z = origin.z - (normal.x * (x - origin.x) + normal.y * (y - origin.y)) / normal.z;
  return toPlane({ x, y, z });
}

PlaneFit fitPlane(const Array<Vec3>& points)
{
  PlaneFit fit;
  if (points.empty())
    return fit;
  for (const Vec3& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return fit;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points)
  {
    lo = { std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z) };
    hi = { std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z) };
  }
  fit.ok = true;
  // Halves first: neither the center nor the half extents can overflow.
  const Vec3 center{ 0.5 * lo.x + 0.5 * hi.x, 0.5 * lo.y + 0.5 * hi.y, 0.5 * lo.z + 0.5 * hi.z };
  const Vec3 half{ 0.5 * hi.x - 0.5 * lo.x, 0.5 * hi.y - 0.5 * lo.y, 0.5 * hi.z - 0.5 * lo.z };
  const double extent = std::max({ half.x, half.y, half.z });
  if (extent == 0) // a single distinct point
  {
    fit.frame = frameFor(center, { 0, 0, 1 });
    fit.degenerate = true;
    return fit;
  }
  int exponent = 0;
  std::frexp(extent, &exponent);
  auto toUnit = [&](const Vec3& p) {
    const Vec3 d = sub(p, center);
    return Vec3{ std::ldexp(d.x, -exponent), std::ldexp(d.y, -exponent),
      std::ldexp(d.z, -exponent) };
  };
  const Vec3 h{ std::ldexp(half.x, -exponent), std::ldexp(half.y, -exponent),
    std::ldexp(half.z, -exponent) };
  fit.diagonal = std::ldexp(2 * std::sqrt(dot(h, h)), exponent);

  // Centroid and scatter matrix in the unit box.
  Vec3 mean;
  for (const Vec3& p : points)
  {
    const Vec3 q = toUnit(p);
    mean = { mean.x + q.x, mean.y + q.y, mean.z + q.z };
  }
  mean = scaled(mean, 1.0 / static_cast<double>(points.size()));
  Matrix3 scatter{};
  for (const Vec3& p : points)
  {
    const Vec3 d = sub(toUnit(p), mean);
    const double c[3] = { d.x, d.y, d.z };
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        scatter[i][j] += c[i] * c[j];
  }
  Matrix3 vectors;
  jacobi(scatter, vectors);
  std::array<int, 3> order{ 0, 1, 2 };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return scatter[a][a] < scatter[b][b] || (scatter[a][a] == scatter[b][b] && a < b);
  });
  auto column = [&](int k) { return Vec3{ vectors[0][k], vectors[1][k], vectors[2][k] }; };
  const double largest = scatter[order[2]][order[2]];
  Vec3 normal = column(order[0]);
  // Collinear points (the two smallest spreads vanish next to the largest):
  // any plane through the line fits; take the one whose normal is closest to z.
  if (scatter[order[1]][order[1]] <= 1e-20 * largest)
  {
    fit.degenerate = true;
    const Vec3 d = normalized(column(order[2]));
    normal = sub(axis(2), scaled(d, d.z));
    if (dot(normal, normal) < 1e-12)
      normal = sub(axis(0), scaled(d, d.x));
  }
  const Vec3 origin{ center.x + std::ldexp(mean.x, exponent),
    center.y + std::ldexp(mean.y, exponent), center.z + std::ldexp(mean.z, exponent) };
  fit.frame = frameFor(origin, normal);

  const Vec3& n = fit.frame.normal;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const double d = std::ldexp(std::fabs(dot(sub(toUnit(points[i]), mean), n)), exponent);
    if (d > fit.maxDistance)
    {
      fit.maxDistance = d;
      fit.farthest = i;
    }
  }
  return fit;
}

std::string formatPoint3(const Vec3& p)
{
  return "(" + formatNumber(p.x) + ", " + formatNumber(p.y) + ", " + formatNumber(p.z) + ")";
}

std::string PlaneMap::choose(const Array<Vec3>& points, bool projectToXY, double roundoff)
{
  input = &points;
  fitted = projected = false;
  inputOf.clear();
  planeZ = points.empty() ? 0.0 : points.front().z;
  const bool constantZ =
    std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return p.z == planeZ; });
  if (constantZ)
    return {};
  if (projectToXY)
  {
    double sum = 0.0;
    for (const Vec3& p : points)
      sum += p.z / static_cast<double>(points.size()); // no overflow at large z
    planeZ = sum;
    projected = true;
    // A vertical plane at any angle to the axes (a review: a Slice at x = 0.1
    // came out as a padded box): within the fit's tolerance, not exactly.
    if (xyOnOneLine(points, relativeTolerance, roundoff))
      return "projected onto the XY plane (ProjectToXYPlane), the input points lie on one line, "
             "which has no area to mesh (the input stands in a vertical plane or surface); turn "
             "ProjectToXYPlane off (osm-mesh: leave out --project-xy) to mesh a vertical plane in "
             "its own plane";
    return {};
  }
  const PlaneFit fit = fitPlane(points);
  if (!fit.ok)
    return "the input points have no best-fitting plane";
  // Rounding each coordinate by roundoff of it moves a point by up to
  // sqrt(3) roundoff of its largest coordinate off the plane, and the fit
  // through the moved points by about as much again.
  double largest = 0.0;
  for (const Vec3& p : points)
    largest = std::max({ largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z) });
  const double rounding = 4 * roundoff * largest;
  if (!fit.coplanar(relativeTolerance, rounding))
  {
    const std::string distance = " is " + generalText(fit.maxDistance, 6) +
      " from their best-fitting plane (the tolerance is " + generalText(relativeTolerance, 6) +
      " times the bounding box diagonal" +
      (rounding > 0 ? " plus 4 times the coordinates' rounding, " + generalText(roundoff, 6) +
            ", of the largest coordinate: " +
            generalText(relativeTolerance * fit.diagonal + rounding, 6) + ")"
                    : ": " + generalText(relativeTolerance * fit.diagonal, 6) + ")");
    return "the input points are not coplanar: point " + std::to_string(fit.farthest) + " at " +
      formatPoint3(points[fit.farthest]) + distance +
      "; turn on ProjectToXYPlane (osm-mesh: --project-xy) to mesh their projection onto the "
      "XY plane";
  }
  fitted = true;
  // Within the tolerance of the fit, the normal's tilt is rounding too: a
  // vertical Slice's float points tilt it by about 1e-5 (a review: such
  // planes came out turned either way).
  const double tilt = 4 * (relativeTolerance * fit.diagonal + rounding) / fit.diagonal;
  frame = frameFor(fit.frame.origin, fit.frame.normal, std::isfinite(tilt) ? tilt : 1e-9);
  return {};
}

void PlaneMap::indexInputPoints(const Array<Point>& planar)
{
  if (!fitted)
    return;
  inputOf.reserve(planar.size());
  for (std::size_t i = 0; i < planar.size(); ++i)
    inputOf.emplace(keyOf(planar[i]), i); // keeps the first of equal points
}

Vec3 PlaneMap::toSpace(const Point& q, long long inputIndex) const
{
  if (!fitted)
    return Vec3{ q.x, q.y, planeZ };
  if (inputIndex < 0)
  {
    const auto it = inputOf.find(keyOf(q));
    inputIndex = it == inputOf.end() ? -1 : static_cast<long long>(it->second);
  }
  return inputIndex >= 0 ? (*input)[static_cast<std::size_t>(inputIndex)] : frame.fromPlane(q);
}

std::size_t PlaneMap::KeyHash::operator()(const Key& k) const
{
  return std::hash<std::uint64_t>()(k.first * 0x9E3779B97F4A7C15ULL ^ k.second);
}

PlaneMap::Key PlaneMap::keyOf(const Point& p)
{
  std::uint64_t x, y;
  const double px = p.x == 0 ? 0.0 : p.x; // -0 and +0 are the same point
  const double py = p.y == 0 ? 0.0 : p.y;
  std::memcpy(&x, &px, sizeof x);
  std::memcpy(&y, &py, sizeof y);
  return { x, y };
}

} // namespace osm
