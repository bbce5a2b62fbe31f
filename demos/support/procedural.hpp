// A procedural colonnade (ground slab and rows of box columns) as GPU meshes and a draw list:
// a scene with depth complexity that needs no file, for tests and as the demos' fallback.
#pragma once
#include "draw_list.hpp"

#include <vector>

namespace rrc::demo {

struct MeshBuffers {
    Buffer vertices, indices;
    VertexArray vertexArray;
    GLsizei indexCount = 0;
};

struct ProceduralScene {
    std::vector<MeshBuffers> meshes;
    std::vector<DrawCall> draws;
};

// Columns of `columns` x 2 rows along z; units of metres, ground at y = 0.
ProceduralScene makeColonnade(int columns = 8);

// Uploads interleaved position + normal vertices (attributes 0 and 1) and uint32 indices.
MeshBuffers uploadMesh(const std::vector<float>& positionsAndNormals, const std::vector<uint32_t>& indices);

} // namespace rrc::demo
