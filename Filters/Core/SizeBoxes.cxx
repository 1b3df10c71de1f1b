#include "SizeBoxes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace osm
{
namespace
{

/// The area of b within r (0 where they do not meet).
double areaWithin(const Bounds& b, const Bounds& r)
{
  const double w = std::min(b.hi.x, r.hi.x) - std::max(b.lo.x, r.lo.x);
  const double h = std::min(b.hi.y, r.hi.y) - std::max(b.lo.y, r.lo.y);
  return w > 0 && h > 0 ? w * h : 0.0;
}

} // namespace

SizeBoxes::SizeBoxes(const Array<SizeBox>& input)
  : boxes(input)
{
  if (boxes.empty())
    return;
  all = boxes.front().box;
  loosest2 = std::numeric_limits<double>::infinity();
  for (const SizeBox& s : boxes)
  {
    all.lo = { std::min(all.lo.x, s.box.lo.x), std::min(all.lo.y, s.box.lo.y) };
    all.hi = { std::max(all.hi.x, s.box.hi.x), std::max(all.hi.y, s.box.hi.y) };
    loosest2 = std::min(loosest2, s.maxEdgeLength * s.maxEdgeLength);
  }
  // About one cell per box, up to 512 x 512, and coarser where boxes overlap
  // so much that listing each in every cell it meets would take more than
  // 16 entries per box (10,000 boxes over the whole span took 1.4 s).
  int side = std::clamp(static_cast<int>(std::ceil(std::sqrt(double(boxes.size())))), 1, 512);
  const double cap = 16.0 * double(boxes.size()) + 4096;
  for (;; side = (side + 1) / 2)
  {
    nx = all.width() > 0 ? side : 1;
    ny = all.height() > 0 ? side : 1;
    double entries = 0;
    for (const SizeBox& s : boxes)
      entries += double(cellX(s.box.hi.x) - cellX(s.box.lo.x) + 1) *
        (cellY(s.box.hi.y) - cellY(s.box.lo.y) + 1);
    if (entries <= cap || side == 1)
      break;
  }
  Array<int> count(std::size_t(nx) * ny + 1, 0);
  auto forCells = [&](const Bounds& b, auto&& f) {
    for (int j = cellY(b.lo.y); j <= cellY(b.hi.y); ++j)
      for (int i = cellX(b.lo.x); i <= cellX(b.hi.x); ++i)
        f(j * nx + i);
  };
  for (const SizeBox& s : boxes)
    forCells(s.box, [&](int c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c)
    count[c] += count[c - 1];
  cellStart = count;
  cellBoxes.resize(count.back());
  cellMin2.assign(std::size_t(nx) * ny, std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < boxes.size(); ++k)
  {
    const double h2 = boxes[k].maxEdgeLength * boxes[k].maxEdgeLength;
    forCells(boxes[k].box, [&](int c) {
      cellBoxes[count[c]++] = static_cast<int>(k);
      cellMin2[c] = std::min(cellMin2[c], h2);
    });
  }
}

int SizeBoxes::cellX(double x) const
{
  // Clamped before the conversion: a large triangle reaches far beyond.
  const double t = (x - all.lo.x) / all.width() * nx;
  return nx == 1 ? 0 : static_cast<int>(std::clamp(t, 0.0, nx - 1.0));
}

int SizeBoxes::cellY(double y) const
{
  const double t = (y - all.lo.y) / all.height() * ny;
  return ny == 1 ? 0 : static_cast<int>(std::clamp(t, 0.0, ny - 1.0));
}

bool SizeBoxes::tooLong(const Point& a, const Point& b, const Point& c, double longest2) const
{
  if (boxes.empty() || !(longest2 > loosest2) || outsideBounds(a, b, c, all))
    return false;
  const Bounds t{ { std::min({ a.x, b.x, c.x }), std::min({ a.y, b.y, c.y }) },
    { std::max({ a.x, b.x, c.x }), std::max({ a.y, b.y, c.y }) } };
  for (int j = cellY(t.lo.y); j <= cellY(t.hi.y); ++j)
    for (int i = cellX(t.lo.x); i <= cellX(t.hi.x); ++i)
    {
      const int cell = j * nx + i;
      if (!(longest2 > cellMin2[cell])) // within every bound of this cell's boxes
        continue;
      for (int k = cellStart[cell]; k < cellStart[cell + 1]; ++k)
      {
        const SizeBox& s = boxes[cellBoxes[k]];
        if (longest2 > s.maxEdgeLength * s.maxEdgeLength && !outsideBounds(a, b, c, s.box))
          return true;
      }
    }
  return false;
}

bool SizeBoxes::covers(const Bounds& b) const
{
  if (boxes.empty() || !within(b, all))
    return false;
  // A box that holds b holds its corner, and is listed in the corner's cell.
  const int cell = cellY(b.lo.y) * nx + cellX(b.lo.x);
  for (int k = cellStart[cell]; k < cellStart[cell + 1]; ++k)
    if (within(b, boxes[cellBoxes[k]].box))
      return true;
  return false;
}

double SizeBoxes::pointsNeeded(const Bounds& within) const
{
  // A triangle with no edge longer than h has at most the area of the
  // equilateral one (sqrt(3)/4 h^2), and a triangulation at most about twice
  // as many triangles as vertices. Areas are clipped to the mesh's box, so
  // that a bound larger than its region counts for nothing, not infinity.
  const auto points = [](double area, double edge) {
    return area == 0 ? 0.0 : area / (0.8660254037844386 * edge * edge);
  };
  double each = 0, tightest = std::numeric_limits<double>::infinity();
  for (const SizeBox& s : boxes)
  {
    each += points(areaWithin(s.box, within), s.maxEdgeLength);
    tightest = std::min(tightest, s.maxEdgeLength);
  }
  return boxes.empty() ? 0.0 : std::min(each, points(areaWithin(all, within), tightest));
}

} // namespace osm
