// The GL side of a Scene: one VAO with its vertex and index buffers per primitive, mipmapped
// textures (base colour sRGB, normal maps linear), and per skin two joint-matrix SSBOs (current,
// previous). forEachDraw() hands the caller one DrawItem per visible primitive to set uniforms.
#pragma once
#include "scene_state.hpp"

#include <rrc/gl_object.hpp>

#include <glm/mat4x4.hpp>

#include <functional>
#include <map>

namespace rrc::scene {

// Vertex attribute locations of every primitive's VAO. Joints are integer attributes (read them
// as `uvec4`); a primitive without an attribute leaves its location disabled.
enum Attribute : GLuint { kPosition = 0, kNormal = 1, kUv0 = 2, kTangent = 3, kJoints = 4, kWeights = 5 };

// SSBO binding points of the joint matrices (std430 `mat4[]`), the same as RRC_BONES_BINDING and
// RRC_PREV_BONES_BINDING in <rrc/skinning.vert>, so that snippet works unchanged.
inline constexpr GLuint kJointsBinding = 3;
inline constexpr GLuint kPrevJointsBinding = 4;

struct DrawItem {
    uint32_t node = 0, mesh = 0, primitive = 0;
    // Object to world, now and at the previous frame. For skinned draws: the skin's anchor
    // (SceneState::skinModel), with the joint matrices relative to it.
    glm::dmat4 world{1.0}, previousWorld{1.0};
    const Material* material = nullptr;      // null: the glTF default material (white, rough)
    GLuint baseColorTexture = 0;             // GL_SRGB8_ALPHA8; 0 when the material has none
    GLuint normalTexture = 0;                // GL_RGBA8; 0 when none
    int skin = kNone;                        // >= 0: its joint SSBOs are bound (kJointsBinding...)
    bool hasNormals = false, hasUv0 = false, hasTangents = false;
    GLuint vertexArray = 0;
    GLsizei indexCount = 0;

    // Binds the VAO and draws the triangles (GL_UNSIGNED_INT indices); leaves the VAO unbound.
    void draw() const;
};

class GpuScene {
public:
    // Uploads every mesh, the textures materials use, and joint buffers sized for each skin. Fails
    // (SceneInvalid) when the scene exceeds GL limits (texture size, SSBO size, index count).
    static Result<GpuScene> upload(const Scene& scene);

    // Copies the current and previous joint matrices of every skin to their SSBOs; call once per
    // frame after SceneState::advance() / update().
    void updateJoints(const SceneState& state);

    // Calls `fn` for each primitive of each mesh node reachable from the scene's roots, with the
    // state's world matrices; binds the item's joint SSBOs first when it is skinned. `state` must
    // belong to the Scene this was uploaded from.
    void forEachDraw(const SceneState& state, const std::function<void(const DrawItem&)>& fn) const;

    GLuint jointBuffer(size_t skin) const { return skins_[skin].current.id(); }
    GLuint previousJointBuffer(size_t skin) const { return skins_[skin].previous.id(); }
    // The GL texture made for glTF texture `texture` in the given colour space (0 if unused).
    GLuint texture(int texture, bool srgb) const;

private:
    struct GpuPrimitive {
        Buffer vertices, indices;
        VertexArray vao;
        GLsizei indexCount = 0;
        bool normals = false, uv0 = false, tangents = false, skinned = false;
    };
    struct GpuSkin {
        Buffer current, previous;
        size_t joints = 0;
    };
    std::vector<std::vector<GpuPrimitive>> meshes_;
    std::map<std::pair<int, bool>, Texture> textures_;   // (glTF texture, sRGB) -> GL texture
    std::vector<std::pair<GLuint, GLuint>> materialTextures_;  // per material: base colour, normal
    std::vector<GpuSkin> skins_;
};

} // namespace rrc::scene
