// Input cleaning: the combinatorial repairs done before meshing, and with a
// merge tolerance the snapping of points onto segments (Snap.h). (Geometric
// repairs within rounding — vertices on segments, overlaps, crossings — are
// found while stitching, by walking the overlay: see Stitch.h.)
#ifndef osm_Clean_h
#define osm_Clean_h

#include "HugePages.h"
#include "Pslg.h"
#include "Statistics.h"

#include <functional>
#include <string>
#include <vector>

namespace osm
{

struct CleanPslg
{
  Array<Point> points;      ///< distinct, finite
  Array<Segment> segments;  ///< distinct, no zero length, (lo, hi) index order
  Array<int> segmentOrigin; ///< per segment: the first input segment it came from
  Array<int> pointOf;       ///< per input point: its index in points
};

/// The first input point that became clean point v (the one that messages
/// name), given CleanPslg::pointOf.
int firstInputPoint(const Array<int>& pointOf, int v);

/// Whether point i may join point j within the merge tolerance (all may
/// when empty).
using JoinFilter = std::function<bool(int i, int j)>;

/// Check and clean the input. Returns an empty string, or an error naming the
/// offending item (a non-finite coordinate, an index out of range).
/// Points within mergeTolerance of an earlier point are merged into it, and
/// (with snap) segments split at the points within mergeTolerance of them
/// (Snap.h). A point joins the first earlier one within mergeTolerance that
/// mayJoin allows.
std::string cleanPslg(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double mergeTolerance = 0.0, const PointFormat& format = {},
  bool snap = true, const JoinFilter& mayJoin = {});

/// "(x, y)", each by formatNumber: digits enough to read back exactly, no more.
std::string formatPoint(const Point& p);

/// x with 15 significant digits, or 16 or 17 if it needs them to read back
/// exactly ("30", "12.5", "1e-10", "0.33333333333333331").
std::string formatNumber(double x);

/// x to two significant digits, for sizes that are only a rule of thumb.
std::string roughNumber(double x);

/// The point written by format, or by formatPoint when format is empty.
inline std::string formatPoint(const Point& p, const PointFormat& format)
{
  return format ? format(p) : formatPoint(p);
}

/// "point N at (x, y)": input point n as the user numbers it, at the input's
/// own coordinates (a working point scaled back may differ in its last digit).
inline std::string namePoint(const Pslg& input, int n, const PointFormat& format)
{
  return "point " + std::to_string(n) + " at " +
    formatPoint(input.points[static_cast<std::size_t>(n)], format);
}

} // namespace osm

#endif
