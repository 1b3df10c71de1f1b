#include "Mesher.h"

namespace osm
{
// Placeholder until the algorithm lands: says so honestly, never pretends to mesh.
Result mesh(const Pslg&, const Options&, Progress*)
{
  Result r;
  r.error = "Overlay Stitch Meshing is not implemented yet in this build";
  return r;
}
double predictedMaxAngleDeg(double)
{
  return 180.0;
}
EdgeClass edgeClass(std::uint8_t flags)
{
  if (flags & EdgeInput)
    return EdgeClass::Input;
  if (flags & EdgeDiscarded)
    return EdgeClass::Discarded;
  if (flags & EdgeCrossed)
    return EdgeClass::Kept;
  return EdgeClass::Uncrossed;
}
}
