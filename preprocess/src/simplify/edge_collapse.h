#pragma once
// The collapse loop behind CollapseCost::Bending and CollapseCost::Distance: a priority queue of
// edges with lazily completed costs, the safety guards, and the quadric memory.

#include "simplify/collapse_quadrics.h"
#include "simplify/edge_energy.h"
#include "shared/triangle_angles.h"

#include "meshprep/core/mesh.h"
#include "meshprep/preprocess/simplify/simplify.h"

#include <functional>
#include <vector>

namespace meshprep::detail {

/// Collapse edges until `target` faces remain or no edge may go. `quadrics` (vertex_quadrics)
/// are accumulated into the kept vertices. A collapse that merges vertex v may not take the
/// quadric's RMS plane distance above `error_cap[v]` (nor above params.max_error); non-manifold
/// vertices never move. `merged_into[v]` is set to the vertex v was collapsed into (entries of
/// vertices that stay are left alone). The mesh is not garbage-collected. Fills the counters of
/// `result` (collapses, rejections, energy evaluations). `reshape` (if given) is called each
/// time the face count halves (Reshape::Relax) and when no edge may go before the target
/// (Reshape::FlipAndRelax); when it returns true (it changed the mesh) every edge is queued
/// again; a stuck queue is restarted a few times at most and only while that still collapses
/// something.
enum class Reshape { Relax, FlipAndRelax };
using ReshapeCallback = std::function<bool(Reshape)>;
/// No collapse turns a face out of `field` (triangle_angles.h).
void collapse_edges(TriMesh& mesh, std::size_t target, const SimplifyParams& params, const CollapseScales& scales,
                    std::vector<Quadric>& quadrics, const std::vector<double>& error_cap,
                    std::vector<int>& merged_into, SimplifyResult& result, const HeightField& field,
                    const ReshapeCallback& reshape = {});

}  // namespace meshprep::detail
