// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
/**
 * @class   vtkOverlayStitchMesher
 * @brief   triangulate planar line data so that no angle exceeds about 170 degrees
 *
 * vtkOverlayStitchMesher meshes a Planar Straight Line Graph given as
 * vtkPolyData (or vtkUnstructuredGrid, whose vertex, poly-vertex, line,
 * polyline, triangle, quad, pixel, polygon and strip cells are read as
 * polydata's, its quadratic, cubic and Lagrange curves and faces through
 * their nodes, a curve as the polyline of its nodes and a face as the polygon
 * of its boundary's nodes, and its other cells, volumes and Bezier cells,
 * ignored with a warning naming the first) with Overlay Stitch Meshing (OSM). Line and polyline
 * cells become segments between consecutive points, polygon cells contribute their closed edge
 * loops, vertex cells (and every other input point) are meshed as isolated points. Triangle strips,
 * empty cells, lines with fewer than 2 points and polygons with fewer than 3 points (a last point
 * repeating the first not counted) are ignored, with one warning that counts them by kind.
 *
 * The input points may lie in any plane:
 * - in a plane z = constant, they are meshed as they are;
 * - otherwise, if they are coplanar (every point within 1e-9 of the bounding
 *   box diagonal from their least-squares plane, plus for float points 4
 *   times 2^-24 of the largest coordinate), they are meshed in that
 *   plane and the output is mapped back to 3D: input vertices keep their
 *   original coordinates bit for bit, new points lie in the fitted plane;
 * - otherwise the run fails with an error naming the point farthest from the
 *   plane and its distance.
 * With ProjectToXYPlane on, any input not in a plane z = constant is instead
 * projected onto the XY plane (z dropped) and the outputs lie in the plane
 * z = the mean z of the input points.
 *
 * Hole seeds come from the HolePoints property and, when UseInputHolePoints
 * is on, from the input's field data array "HolePoints" (2 or 3 components,
 * (x, y) or (x, y, z); the .poly reader writes 3). For input meshed in a
 * fitted plane, (x, y, z) seeds are projected orthogonally onto that plane and
 * (x, y) seeds, the property's among them, are moved along z onto it; in a
 * plane that contains the z direction (x = c, y = c, or within the rounding
 * of float points of it) an (x, y) seed names no single point, and the run
 * fails: give such seeds with 3 components.
 *
 * The mesher runs in three phases: an overlay Delaunay mesh of the input
 * points whose angles are at least MinimumAngle (θ1); stitching, which keeps
 * the overlay edges that input segments cross at good angles and discards the
 * others; completion, which triangulates the remaining faces minimizing their
 * largest angle. Every output angle is at most 180° − θ2 (about 170° at the
 * default θ1 = 30°).
 *
 * The filter has three output ports, whose points are double whatever the
 * input's type (float input points give double output points; there is no
 * OutputPointsPrecision): the angle bound holds for the double coordinates the
 * mesher computes, and rounded to float the thinnest triangles (angles of
 * 1e-4 degrees occur along stitched segments) could turn over.
 * - port 0 (Mesh): the conforming triangulation. Point data `VertexOrigin`
 *   (0 input vertex, 1 overlay Steiner point, 2 stitch point on a segment,
 *   3 other: a crossing of input segments, or a point splitting a
 *   completed edge longer than MaximumEdgeLength) and `InputPointId` (an
 *   input vertex's id in the input, -1 for the others; with `InputBlockId`
 *   for a composite input) and, with InterpolatePointData, the input's point
 *   arrays; cell data `MinAngle`, `MaxAngle` (degrees) and `RegionId`,
 *   `RegionAttribute` when the input has regional attributes, and, with
 *   PassCellData, the input polygons' cell arrays with `InputCellId` (and
 *   `InputBlockId`); field data: one single-value array per run statistic.
 * - port 1 (Edges): every overlay edge and every input subsegment as line
 *   cells, with cell data `Overlay`, `Kept`, `Discarded`, `Input` (0/1) and
 *   the categorical `EdgeClass` (0 uncrossed, 1 kept, 2 discarded, 3 input;
 *   the names are in the field data string array `EdgeClassNames`), and,
 *   with PassCellData, the input cells' arrays along the subsegments with
 *   `InputCellId` (and `InputBlockId`). The README describes every array.
 * - port 2 (Overlay): the phase-1 overlay triangulation, for inspection. It
 *   is refined to θ1 within the bounding box of the segments (enclosed
 *   domain) or of the points (hull domain), and everywhere with the box
 *   domain; outside it no output triangle comes from it, and it stays coarse.
 *
 * Bad input (NaN coordinates, crossing segments when ResolveIntersections is
 * off, points not in one plane, malformed cell arrays, ...) is reported
 * through vtkErrorMacro with the reason, and all outputs are left empty; in a
 * serial run RequestData then returns 0, so that the executive's Update()
 * returns 0 (in a parallel run every rank returns 1, so that filters
 * downstream run on every rank alike). Progress is reported through
 * every phase (input, clean, overlay, stitch, complete, domain, output) and
 * GetAbortExecute() is polled: an abort ends the run with empty outputs and
 * the warning "Meshing aborted by the user", given once while the flag stays
 * set (RequestData returns 1, as VTK's filters do on an abort). A failed
 * serial run also makes VTK's executive print the failed request (with
 * ReportFailureToPipeline off, it does not). A NaN given to a clamped
 * setter is kept, not clamped, and refused by the run with an error.
 *
 * The class uses only API that VTK 9.1 also has.
 *
 * @sa
 * vtkDelaunay2D
 */

#ifndef vtkOverlayStitchMesher_h
#define vtkOverlayStitchMesher_h

#include "OverlayStitchFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <vector> // For HolePoints

class vtkMultiProcessController;

class OVERLAYSTITCHFILTERS_EXPORT vtkOverlayStitchMesher : public vtkPolyDataAlgorithm
{
public:
  static vtkOverlayStitchMesher* New();
  vtkTypeMacro(vtkOverlayStitchMesher, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What part of the plane the output triangles cover.
   */
  enum DomainTypes
  {
    /// DOMAIN_ENCLOSED if the segments enclose a region with an input point on
    /// its boundary (where segments cross, regions a speck across do not
    /// count), else DOMAIN_HULL
    DOMAIN_AUTO = 0,
    DOMAIN_ENCLOSED = 1, ///< regions enclosed by segments, minus holes
                         /// the convex hull of the input points, minus holes (DOMAIN_BOX, with a
                         /// warning, where the hull has no area)
    DOMAIN_HULL = 2,
    DOMAIN_BOX = 3 ///< the overlay's padded box: 4 times the input's larger extent
  };

  ///@{
  /**
   * θ1, the smallest angle of the phase-1 overlay mesh, in degrees (1 to 35,
   * default 30). The output's largest angle is bounded by 180° − θ2, where θ2
   * grows with θ1 (a larger θ1, a lower bound): 30° gives about 170°. Above 30° nothing is
   * guaranteed: the mesh grows several times larger, and from about 32.5° (31.7° with
   * GapRatioOverlay) the refinement may not end (an error after its cap on
   * Steiner points).
   */
  vtkSetClampMacro(MinimumAngle, double, 1.0, 35.0);
  vtkGetMacro(MinimumAngle, double);
  ///@}

  ///@{
  /**
   * If greater than 0, no edge of the mesh is longer: overlay triangles with
   * a longer edge are refined further, and the few longer diagonals that
   * completion makes are split (a warning names any that cannot be). 0 (the
   * default) means no limit.
   */
  vtkSetClampMacro(MaximumEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  ///@{
  /**
   * The part of the plane to mesh (see DomainTypes). Default DOMAIN_AUTO.
   */
  vtkSetClampMacro(Domain, int, DOMAIN_AUTO, DOMAIN_BOX);
  vtkGetMacro(Domain, int);
  void SetDomainToAuto() { this->SetDomain(DOMAIN_AUTO); }
  void SetDomainToEnclosed() { this->SetDomain(DOMAIN_ENCLOSED); }
  void SetDomainToHull() { this->SetDomain(DOMAIN_HULL); }
  void SetDomainToBox() { this->SetDomain(DOMAIN_BOX); }
  ///@}

  ///@{
  /**
   * If on (the default), input segments that cross are split at their
   * intersection; if off, crossing segments are an error naming them.
   */
  vtkSetMacro(ResolveIntersections, vtkTypeBool);
  vtkGetMacro(ResolveIntersections, vtkTypeBool);
  vtkBooleanMacro(ResolveIntersections, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Input points at most this distance apart are merged into the first of them
   * (counted in the statistic DuplicatePointsMerged), and segments split at
   * the points within this distance of them, bending to pass through them
   * (PointsSnappedOntoSegments): a border digitised twice becomes one. Where
   * crossing segments are split, crossings within this distance of a point or of
   * another crossing join it: segments meant to meet at one point, whose
   * rounded crossings scatter, meet there. 0, the default, merges only exact
   * duplicates. A negative value is clamped to 0; infinity and NaN are kept,
   * and refused when meshing (clamping infinity to the largest double merged
   * every point into one).
   */
  virtual void SetMergeTolerance(double tolerance);
  vtkGetMacro(MergeTolerance, double);
  ///@}

  ///@{
  /**
   * If on, input points that are not in a plane z = constant (whether they
   * lie in a tilted plane or in no plane at all) are projected onto the XY
   * plane: z is dropped, x and y are meshed as they are, and the outputs lie
   * in the plane z = the mean z of the input points (a warning says so), the
   * input z kept as the point array `InputZ`. Input in a vertical plane
   * projects onto a line, which is an error. Points in a plane z = constant
   * are never changed. Default off: tilted coplanar input is meshed in its
   * own plane, other input is an error.
   */
  vtkSetMacro(ProjectToXYPlane, vtkTypeBool);
  vtkGetMacro(ProjectToXYPlane, vtkTypeBool);
  vtkBooleanMacro(ProjectToXYPlane, vtkTypeBool);
  ///@}

  ///@{
  /**
   * If on, the maximum area of each region seed in the input's field data
   * array "RegionAttributes" (its 4th component, when positive; the last
   * seed's, where several share a region) bounds every triangle of its
   * region, as Triangle's -a does. Off (the default), as Triangle without
   * -a, areas are ignored with a warning.
   */
  vtkSetMacro(ApplyRegionAreas, vtkTypeBool);
  vtkGetMacro(ApplyRegionAreas, vtkTypeBool);
  vtkBooleanMacro(ApplyRegionAreas, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The overlay's quality. The paper proves the largest-angle bound for an
   * overlay of gap-ratio quality (every triangle's circumradius at most
   * Gamma times the distance from each corner to its nearest neighbour).
   * Off (the default), the overlay bounds radius / shortest edge, as
   * Delaunay refinement does: up to 12.5 times fewer triangles on real inputs,
   * all meshed below 150 degrees, but no proof; a mesh from it with an angle
   * above the bound is made again from a gap-ratio overlay, with a warning
   * (statistic GapRatioOverlay 1). On: the gap-ratio overlay at once.
   */
  vtkSetMacro(GapRatioOverlay, vtkTypeBool);
  vtkGetMacro(GapRatioOverlay, vtkTypeBool);
  vtkBooleanMacro(GapRatioOverlay, vtkTypeBool);
  ///@}

  ///@{
  /**
   * If on (the default), the input's field data array "HolePoints" (2 or 3
   * components, (x, y) or (x, y, z); the .poly reader writes 3) adds hole
   * seeds to those of the HolePoints property.
   */
  vtkSetMacro(UseInputHolePoints, vtkTypeBool);
  vtkGetMacro(UseInputHolePoints, vtkTypeBool);
  vtkBooleanMacro(UseInputHolePoints, vtkTypeBool);
  ///@}

  ///@{
  /**
   * If on (the default), a serial run that fails returns failure to the
   * pipeline, so that Update() returns 0; either way the error is reported
   * and the outputs are empty. ParaView's plugin turns it off (its XML): in
   * ParaView 5.11 a filter that returns failure during a render leaves the
   * view and the Information panel on its last output for good, even once
   * the run succeeds again (a review; its stock filters do the same).
   */
  vtkSetMacro(ReportFailureToPipeline, vtkTypeBool);
  vtkGetMacro(ReportFailureToPipeline, vtkTypeBool);
  vtkBooleanMacro(ReportFailureToPipeline, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Stop with an error when the overlay of a meshing round would need more
   * Steiner points than this (as the statistic OverlaySteinerPoints counts
   * the last round's: the 4 corners of its padding box and the points
   * refining it, in the padding too; not the points put on segments): never
   * an invalid or partial mesh. 0 (the default) means no cap.
   */
  vtkSetClampMacro(MaximumSteinerPoints, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MaximumSteinerPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * Whether to carry the input's point data to the Mesh's vertices. Default
   * on. An input vertex keeps its values; a point the mesher puts on a
   * segment takes the values linear along that segment; any other point
   * (Steiner points) the values linear in the triangle of those points that
   * holds it, so that a field linear over the input is reproduced.
   * Floating-point arrays are interpolated so; other arrays (labels, ids,
   * strings) take the value of the input point with the largest weight,
   * except Triangle's vertex markers (a "PointMarker" array, as
   * vtkTrianglePolyReader writes them), which follow Triangle's rules: a
   * point's own nonzero marker, else a nonzero marker of a segment it lies
   * on (the cells' "SegmentMarker"), else 1 on the mesh's boundary (holes'
   * included), else 0. Costs a third to a half of the core's time on large inputs
   * with point data.
   */
  vtkSetMacro(InterpolatePointData, vtkTypeBool);
  vtkGetMacro(InterpolatePointData, vtkTypeBool);
  vtkBooleanMacro(InterpolatePointData, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Whether to carry the input's cell data to the outputs. Default on.
   * Each triangle of the Mesh takes the tuple of the smallest input polygon
   * around it (the innermost where polygons nest; nothing without polygon
   * cells), each input subsegment of the Edges output (an edge along a
   * line, polyline or polygon of the input) the tuple of the cell it comes
   * from, and "InputCellId" names that cell; every other triangle or edge
   * takes NaN (floating point), 0 (other numbers) or an empty string, and
   * InputCellId -1. Triangle's segment markers (the cells' "SegmentMarker",
   * as vtkTrianglePolyReader writes them) follow Triangle's rules for .edge
   * files: a subsegment's nonzero marker, else 1 on the mesh's boundary
   * (holes' included), else 0.
   * Where segments of several cells overlap, a subsegment takes the first
   * cell's. For an unstructured grid, InputCellId is the cell's id in the
   * grid (in a serial run; distributed over the ranks of a parallel one, it
   * numbers the cells of the gathered input, as for polydata). For a
   * composite input, InputCellId is the cell's id in its block
   * and "InputBlockId" the block's flat index (-1 where no cell is named);
   * in a parallel run where a rank holds only part of a block, the id in
   * that part.
   */
  vtkSetMacro(PassCellData, vtkTypeBool);
  vtkGetMacro(PassCellData, vtkTypeBool);
  vtkBooleanMacro(PassCellData, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Whether to fill output port 1 (Edges). Default on.
   */
  vtkSetMacro(GenerateEdges, vtkTypeBool);
  vtkGetMacro(GenerateEdges, vtkTypeBool);
  vtkBooleanMacro(GenerateEdges, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Whether to fill output port 2 (Overlay). Default on.
   */
  vtkSetMacro(GenerateOverlay, vtkTypeBool);
  vtkGetMacro(GenerateOverlay, vtkTypeBool);
  vtkBooleanMacro(GenerateOverlay, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Hole seed points (x, y): the region bounded by segments that contains a
   * seed is removed from the output, like the holes of Triangle's .poly files.
   * See also UseInputHolePoints. ParaView's HolePoints property passes
   * (x, y) pairs to AddHolePoint, as rows of two columns (a list of odd
   * length loses its last value there, in ParaView's property). With
   * AddHolePointCoordinate, which appends one value (x, then y), a last value
   * without its pair is said in a warning.
   */
  void AddHolePoint(double x, double y);
  void AddHolePointCoordinate(double value);
  void RemoveAllHolePoints();
  int GetNumberOfHolePoints() const;
  void GetHolePoint(int i, double point[2]) const;
  ///@}

  ///@{
  /**
   * The controller whose processes mesh together (default: the global
   * controller at construction). With more than one process, RequestData is
   * collective: every process must update the filter, each with its piece;
   * the pieces are gathered and meshed on process 0, and the other processes'
   * outputs are empty. Set null, or a one-process controller, to mesh each
   * process's input on its own (an MPI application meshing on some ranks
   * only: with the global controller, the other ranks' collectives would
   * meet this filter's and hang, a review).
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  ///@{
  /**
   * Convenience accessors for the outputs: port 0 is GetOutput().
   */
  vtkPolyData* GetEdgesOutput();
  vtkPolyData* GetOverlayOutput();
  ///@}

protected:
  vtkOverlayStitchMesher();
  ~vtkOverlayStitchMesher() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  double MinimumAngle;
  double MaximumEdgeLength;
  int Domain;
  vtkTypeBool ResolveIntersections;
  double MergeTolerance;
  vtkTypeBool ProjectToXYPlane;
  vtkTypeBool UseInputHolePoints;
  vtkTypeBool ReportFailureToPipeline;
  vtkTypeBool ApplyRegionAreas;
  vtkTypeBool GapRatioOverlay;
  vtkIdType MaximumSteinerPoints;
  vtkTypeBool InterpolatePointData;
  vtkTypeBool PassCellData;
  vtkTypeBool GenerateEdges;
  vtkTypeBool GenerateOverlay;
  std::vector<double> HolePoints; // x0, y0, x1, y1, ...
  vtkMultiProcessController* Controller;

private:
  class MeshRun;          // one run of RequestData's steps (in the .cxx)
  bool AbortSaid = false; // the last run was aborted and said so, or followed one that did

  vtkOverlayStitchMesher(const vtkOverlayStitchMesher&) = delete;
  void operator=(const vtkOverlayStitchMesher&) = delete;
};

#endif
