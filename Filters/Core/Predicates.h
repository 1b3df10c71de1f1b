// Exact geometric predicates (adaptive: floating-point filter, exact fallback).
// The sign of each result is always correct; the magnitude is only an estimate.
#ifndef osm_Predicates_h
#define osm_Predicates_h

#include "Geometry.h"

namespace osm
{

/// > 0 if a, b, c turn counter-clockwise, < 0 if clockwise, 0 if collinear.
double orient2d(const Point& a, const Point& b, const Point& c);

/// For a, b, c counter-clockwise: > 0 if d lies strictly inside their circumcircle,
/// < 0 if strictly outside, 0 if on it. (Sign flips if a, b, c are clockwise.)
double incircle(const Point& a, const Point& b, const Point& c, const Point& d);

inline int orientSign(const Point& a, const Point& b, const Point& c)
{
  const double o = orient2d(a, b, c);
  return (o > 0) - (o < 0);
}

} // namespace osm

#endif
