#pragma once
// CDLOD's CPU side (Strugar 2010) over the chunk quadtree (chunk_quadtree.h).
// LOD 0 is the finest (the tree's leaves, stride 1); LOD k nodes have stride
// 2^k and LOD ranges double per level: range(k) = lod0_range_m * 2^k. The
// top LOD (the root) has no range: it covers whatever is left.
//
// Selection (Strugar's quadtree walk): a node of LOD k is drawn when its box
// reaches into range(k) and not into range(k-1); when it reaches into both,
// each child is tried at LOD k-1, and the quarters whose child lies wholly
// outside range(k-1) are drawn with the node's own (LOD k) grid. So every
// point drawn at LOD k lies beyond range(k-1), and every point drawn at LOD
// k+1 or coarser lies beyond range(k).
//
// Morphing (in the vertex shader, shaders/cdlod.vert, mirrored here by
// cdlod_vertex for tests): over [morph_start(k), morph_end(k)) =
// [r * range(k), 0.99 * range(k)), r = 2/3, a vertex of the LOD k grid that
// is odd on that grid slides to its even neighbour (towards lower sample
// indices, along the fine mesh's own edge), so at morph_end the LOD k mesh is
// exactly the LOD k+1 mesh (with zero-area triangles). Cascade: a vertex that
// is fully morphed at LOD k is then morphed by LOD k+1's factor, and so on,
// each factor from the vertex's position at that stage. A vertex's final
// position is therefore a function of its grid position and the eye only,
// whichever node draws it: shared edges between nodes of any two LODs match
// exactly (a finer node's vertices on the boundary with a coarser one lie
// beyond range(k), fully morphed), and a node switching LOD does not pop.
// Needs r >= 0.5 (then LOD k+1 morphing only starts where LOD k's is
// complete).

#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lod/chunk_quadtree.h"

namespace ig::lod {

struct CdlodRanges {
  double lod0_range_m = 3840.0;            // range of LOD 0 (metres)
  double morph_start_ratio = 2.0 / 3.0;    // Strugar's default morph start
  static constexpr double kMorphEndRatio = 0.99;  // margin so boundary vertices are fully morphed in float
  int top_lod = 0;                         // the root's LOD (= tree depth)

  double range(int lod) const;        // infinite for the top LOD
  double morph_end(int lod) const;    // infinite for the top LOD
  double morph_start(int lod) const;
  // Morph factor in [0, 1] of a LOD `lod` vertex at distance d.
  double morph(int lod, double d) const;
};

// One drawn piece: a whole node, or one quarter of it, with the node's grid.
struct CdlodArea {
  int node = 0;
  int quadrant = -1;  // -1: whole node; 0..3: child order (south-west, south-east, north-west, north-east)
  int lod = 0;
};

using BoxVisible = std::function<bool(const glm::dvec3& lo, const glm::dvec3& hi)>;

// Selects the areas to draw for an eye (terrain-local metres); `visible`
// culls boxes (e.g. against the view frustum).
std::vector<CdlodArea> cdlod_select(const ChunkQuadtree& tree, const CdlodRanges& ranges, const glm::dvec3& eye,
                                    const BoxVisible& visible);

// The final (morphed) position of the vertex at sample p of a LOD `lod`
// grid: x, y in (fractional) sample units, z height in metres. What
// shaders/cdlod.vert computes (in float there).
glm::dvec3 cdlod_vertex(const terrain::Heightfield& hf, const CdlodRanges& ranges, glm::ivec2 p, int lod,
                        const glm::dvec3& eye);

}  // namespace ig::lod
