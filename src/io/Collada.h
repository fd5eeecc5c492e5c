#pragma once
// COLLADA (.dae) triangle meshes, as OMPL.app's planar problems store their robots and
// obstacles: every <triangles> element of every geometry a visual-scene node instantiates,
// with the nodes' matrices applied, projected on the mesh's X/Z plane.
#include <array>
#include <string>
#include <vector>

#include "mms/Geometry.h"

namespace mms {

struct ColladaMesh {
  std::vector<std::array<Vec2, 3>> triangles;  // projected; may be degenerate (side faces)
  size_t lineElements = 0;                     // <lines> pieces: no area, left out
  // Mean of the vertex positions the triangles' sources hold (projected): OMPL.app moves a
  // robot's mesh so that this point (assimp's scene centre) is its reference point.
  Vec2 vertexMean{0, 0};
  size_t vertexCount = 0;
};

/// Throws InputError naming the file and the element on malformed XML or references.
ColladaMesh readColladaPlanar(const std::string& file);
/// The same from a document in memory; `source` names it in messages.
ColladaMesh parseColladaPlanar(const std::string& text, const std::string& source);

}  // namespace mms
