// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
#include "OverlayStitchSeeds.h"

#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include "OverlayStitchArrayNames.h"

#include <algorithm>
#include <array>
#include <cmath>

const char* const OverlayStitchSeedReferenceName = "SeedReferencePoints";

namespace
{
using Xyz = std::array<double, 3>;

Xyz Minus(const Xyz& a, const Xyz& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

double NormalLength2(const Xyz& o, const Xyz& a, const Xyz& b)
{
  Xyz u = Minus(a, o), v = Minus(b, o), n;
  vtkMath::Cross(u.data(), v.data(), n.data());
  return vtkMath::Dot(n.data(), n.data());
}

/// The affine map of a plane given by where it takes three of its points.
class PlaneAffineMap
{
public:
  PlaneAffineMap(const std::array<Xyz, 3>& from, const std::array<Xyz, 3>& to)
    : Origin(from[0])
    , U(Minus(from[1], from[0]))
    , V(Minus(from[2], from[0]))
    , ToOrigin(to[0])
    , ToU(Minus(to[1], to[0]))
    , ToV(Minus(to[2], to[0]))
  {
    vtkMath::Cross(this->U.data(), this->V.data(), this->Normal.data());
    Xyz toNormal;
    vtkMath::Cross(this->ToU.data(), this->ToV.data(), toNormal.data());
    const double from2 = vtkMath::Dot(this->Normal.data(), this->Normal.data());
    const double to2 = vtkMath::Dot(toNormal.data(), toNormal.data());
    this->AreaScale = from2 > 0 ? std::sqrt(to2 / from2) : 0.0;
  }

  /// Defined where both triples span a plane.
  bool Defined() const { return this->AreaScale > 0 && std::isfinite(this->AreaScale); }
  double GetAreaScale() const { return this->AreaScale; }

  /// The image of s, a point of the first plane (its distance off it dropped).
  Xyz Map(const Xyz& s) const
  {
    const Xyz w = Minus(s, this->Origin);
    const double uu = vtkMath::Dot(this->U.data(), this->U.data());
    const double uv = vtkMath::Dot(this->U.data(), this->V.data());
    const double vv = vtkMath::Dot(this->V.data(), this->V.data());
    const double wu = vtkMath::Dot(w.data(), this->U.data());
    const double wv = vtkMath::Dot(w.data(), this->V.data());
    const double det = uu * vv - uv * uv;
    const double a = (wu * vv - wv * uv) / det, b = (wv * uu - wu * uv) / det;
    Xyz out;
    for (int k = 0; k < 3; ++k)
    {
      out[k] = this->ToOrigin[k] + a * this->ToU[k] + b * this->ToV[k];
    }
    return out;
  }

  /// (x, y) lifted along z onto the first plane (a seed given as x and y).
  Xyz Lift(double x, double y) const
  {
    const Xyz& n = this->Normal;
    const double z = n[2] != 0
      ? this->Origin[2] - (n[0] * (x - this->Origin[0]) + n[1] * (y - this->Origin[1])) / n[2]
      : this->Origin[2];
    return { x, y, z };
  }

private:
  Xyz Origin, U, V, ToOrigin, ToU, ToV, Normal{};
  double AreaScale = 0.0;
};

/// HolePoints (x, y and perhaps z) mapped, as x, y, z: the plane they are
/// mapped onto may contain the z direction, where (x, y) names no point.
vtkSmartPointer<vtkDoubleArray> MappedHoles(vtkDataArray* holes, const PlaneAffineMap& map)
{
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(holes->GetName());
  out->SetNumberOfComponents(3);
  out->SetNumberOfTuples(holes->GetNumberOfTuples());
  const bool xyz = holes->GetNumberOfComponents() == 3;
  for (vtkIdType i = 0; i < holes->GetNumberOfTuples(); ++i)
  {
    double t[3] = { 0, 0, 0 };
    holes->GetTuple(i, t);
    Xyz to = map.Map(xyz ? Xyz{ t[0], t[1], t[2] } : map.Lift(t[0], t[1]));
    out->SetTuple(i, to.data());
  }
  return out;
}

/// RegionAttributes (x, y, attribute and perhaps a maximum area) mapped, the
/// areas scaled with the plane's.
vtkSmartPointer<vtkDoubleArray> MappedRegions(vtkDataArray* regions, const PlaneAffineMap& map)
{
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->DeepCopy(regions);
  const int components = out->GetNumberOfComponents();
  for (vtkIdType i = 0; i < out->GetNumberOfTuples(); ++i)
  {
    double* t = out->GetPointer(i * components);
    const Xyz to = map.Map(map.Lift(t[0], t[1]));
    t[0] = to[0];
    t[1] = to[1];
    if (components == 4 && t[3] > 0)
    {
      t[3] *= map.GetAreaScale();
    }
  }
  return out;
}

constexpr int kReferencePoints = 4;
} // namespace

//------------------------------------------------------------------------------
void OverlayStitchAddSeedReference(vtkPolyData* output)
{
  const vtkIdType n = output->GetNumberOfPoints();
  if (n < kReferencePoints)
  {
    return;
  }
  auto point = [output](vtkIdType i) {
    Xyz p;
    output->GetPoint(i, p.data());
    return p;
  };
  // The lowest point, the farthest from it, and the farthest from their
  // line span the plane; a fourth, the middle one by id, tells whether the
  // points moved by an affine map (a Warp By Scalar does not).
  vtkIdType ids[kReferencePoints] = { 0, 0, 0, n / 2 };
  for (vtkIdType i = 1; i < n; ++i)
  {
    ids[0] = point(i) < point(ids[0]) ? i : ids[0];
  }
  double best = -1;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double d = vtkMath::Distance2BetweenPoints(point(i).data(), point(ids[0]).data());
    ids[1] = d > best ? i : ids[1];
    best = std::max(best, d);
  }
  best = -1;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double d = NormalLength2(point(ids[0]), point(ids[1]), point(i));
    ids[2] = d > best ? i : ids[2];
    best = std::max(best, d);
  }
  vtkNew<vtkDoubleArray> reference;
  reference->SetName(OverlayStitchSeedReferenceName);
  reference->SetNumberOfComponents(4);
  for (const vtkIdType id : ids)
  {
    const Xyz p = point(id);
    reference->InsertNextTuple4(static_cast<double>(id), p[0], p[1], p[2]);
  }
  reference->InsertNextTuple4(static_cast<double>(n), 0, 0, 0);
  output->GetFieldData()->AddArray(reference);
}

/// Whether every recorded reference point is still a point of data, under
/// any id: the points were renumbered, merged, clipped or added to, but the
/// seeds lie where they were written.
bool RecordedPointsStillThere(vtkDataSet* data, const std::array<Xyz, kReferencePoints>& recorded)
{
  std::array<bool, kReferencePoints> found{};
  Xyz p;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    data->GetPoint(i, p.data());
    for (int k = 0; k < kReferencePoints; ++k)
    {
      found[k] = found[k] || p == recorded[k];
    }
  }
  return std::all_of(found.begin(), found.end(), [](bool f) { return f; });
}

/// What the seeds do when the points were renumbered (their number changed,
/// or the recorded ids name other points) and the recorded points are gone.
const char* const kRenumberedAndMoved =
  "the points have been renumbered, merged or added to (a Clean, an Append) and moved (a "
  "Transform) since the hole and region seeds of its field data were written, so that the seeds "
  "cannot follow them: they are used as they were written; apply the Transform after such "
  "filters, or give the seeds again";

//------------------------------------------------------------------------------
vtkSmartPointer<vtkDataObject> OverlayStitchSeedsFollowingPoints(
  vtkDataObject* input, std::string& note)
{
  auto* data = vtkDataSet::SafeDownCast(input);
  vtkFieldData* field = data ? data->GetFieldData() : nullptr;
  vtkDataArray* reference = field ? field->GetArray(OverlayStitchSeedReferenceName) : nullptr;
  vtkDataArray* holes = field ? field->GetArray(OverlayStitchArrayNames::HolePoints) : nullptr;
  vtkDataArray* regions =
    field ? field->GetArray(OverlayStitchArrayNames::RegionAttributes) : nullptr;
  const vtkIdType n = data ? data->GetNumberOfPoints() : 0;
  if (!reference || reference->GetNumberOfComponents() != 4 ||
    reference->GetNumberOfTuples() != kReferencePoints + 1 || (!holes && !regions))
  {
    return nullptr;
  }
  std::array<Xyz, kReferencePoints> from, to;
  for (int k = 0; k < kReferencePoints; ++k)
  {
    from[k] = { reference->GetComponent(k, 1), reference->GetComponent(k, 2),
      reference->GetComponent(k, 3) };
  }
  // Another number of points: the ids may name others (a review: seeds left
  // behind by a Transform before a Clean or an Append, with no word).
  if (reference->GetComponent(kReferencePoints, 0) != static_cast<double>(n))
  {
    if (!RecordedPointsStillThere(data, from))
    {
      note = kRenumberedAndMoved;
    }
    return nullptr;
  }
  bool moved = false;
  for (int k = 0; k < kReferencePoints; ++k)
  {
    const double id = reference->GetComponent(k, 0);
    if (!(id >= 0 && id < static_cast<double>(n)))
    {
      return nullptr;
    }
    data->GetPoint(static_cast<vtkIdType>(id), to[k].data());
    moved = moved || from[k] != to[k];
  }
  if (!moved)
  {
    return nullptr;
  }
  const PlaneAffineMap map({ from[0], from[1], from[2] }, { to[0], to[1], to[2] });
  // The fourth point where the map takes it, to rounding (float points: 1e-6
  // of the triangle's size): else the points moved by no affine map.
  const Xyz fourth = map.Map(from[3]);
  const double size = std::sqrt(vtkMath::Distance2BetweenPoints(to[0].data(), to[1].data())) +
    std::sqrt(vtkMath::Distance2BetweenPoints(to[0].data(), to[2].data()));
  if (!map.Defined() ||
    !(std::sqrt(vtkMath::Distance2BetweenPoints(fourth.data(), to[3].data())) <= 1e-6 * size))
  {
    // Renumbered in place (a Clean that merged none): the seeds still fit.
    if (RecordedPointsStillThere(data, from))
    {
      return nullptr;
    }
    note = "the points have moved since the hole and region seeds of its field data were "
           "written, by no map of a plane onto a plane (a Warp By Scalar, for instance), or were "
           "renumbered and moved (a Clean after a Transform): the seeds are used as they were "
           "written";
    return nullptr;
  }
  vtkNew<vtkFieldData> moves;
  moves->ShallowCopy(field);
  if (holes && OverlayStitchArrayNames::IsHolePointsShape(holes->GetNumberOfComponents()))
  {
    moves->AddArray(MappedHoles(holes, map));
  }
  if (regions && OverlayStitchArrayNames::IsRegionAttributesShape(regions->GetNumberOfComponents()))
  {
    moves->AddArray(MappedRegions(regions, map));
  }
  vtkSmartPointer<vtkDataSet> copy = vtk::TakeSmartPointer(data->NewInstance());
  copy->ShallowCopy(data);
  copy->SetFieldData(moves);
  return copy;
}
