// GpuScene: vertex data in one immutable buffer per primitive (attributes one after another, one
// VAO binding each), uint32 index buffers, material textures, joint SSBOs; and the draw walk.
#include "gpu_scene.hpp"

#include "gpu_texture.hpp"

#include <climits>
#include <iterator>
#include <tuple>
#include <cstring>

namespace rrc::scene {
namespace {

struct Layout {
    GLuint location;
    const void* data;
    size_t bytes;
    GLint components;
    GLenum type;
    bool integer;
};

template <class T>
Layout layout(GLuint location, const std::vector<T>& v, GLint components, GLenum type, bool integer = false) {
    return {location, v.data(), v.size() * sizeof(T), components, type, integer};
}

GLint glInteger(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}

Result<void> checkLimits(const Scene& scene) {
    const int64_t maxTexture = glInteger(GL_MAX_TEXTURE_SIZE);
    for (size_t i = 0; i < scene.images.size(); ++i)
        if (scene.images[i].width > maxTexture || scene.images[i].height > maxTexture)
            return fail(LogId::SceneInvalid, scene.source + ": image " + std::to_string(i) + " is larger than GL_MAX_TEXTURE_SIZE " +
                                                 std::to_string(maxTexture));
    const int64_t maxBlock = glInteger(GL_MAX_SHADER_STORAGE_BLOCK_SIZE);
    for (size_t s = 0; s < scene.skins.size(); ++s)
        if (int64_t(scene.skins[s].joints.size() * sizeof(glm::mat4)) > maxBlock)
            return fail(LogId::SceneInvalid, scene.source + ": skin " + std::to_string(s) + " has more joints than one SSBO holds (" +
                                                 std::to_string(maxBlock) + " bytes)");
    for (size_t m = 0; m < scene.meshes.size(); ++m)
        for (const Primitive& p : scene.meshes[m].primitives)
            if (p.indices.size() > size_t(INT_MAX) || p.positions.size() > size_t(UINT32_MAX))
                return fail(LogId::SceneInvalid, scene.source + ": mesh " + std::to_string(m) + " is too large for one draw call");
    return {};
}

} // namespace

void DrawItem::draw() const {
    glBindVertexArray(vertexArray);
    glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

Result<GpuScene> GpuScene::upload(const Scene& scene) {
    if (auto r = checkLimits(scene); !r) return r.error();
    GpuScene gpu;
    for (const Mesh& mesh : scene.meshes) {
        auto& primitives = gpu.meshes_.emplace_back();
        for (const Primitive& p : mesh.primitives) {
            GpuPrimitive& out = primitives.emplace_back();
            const Layout attributes[] = {
                layout(kPosition, p.positions, 3, GL_FLOAT), layout(kNormal, p.normals, 3, GL_FLOAT),
                layout(kUv0, p.uv0, 2, GL_FLOAT), layout(kTangent, p.tangents, 4, GL_FLOAT),
                layout(kJoints, p.joints, 4, GL_UNSIGNED_SHORT, true), layout(kWeights, p.weights, 4, GL_FLOAT)};
            // One staging copy so the buffer can be immutable and filled in a single call.
            std::vector<unsigned char> staging;
            std::vector<size_t> offsets;
            for (const Layout& a : attributes) {
                offsets.push_back(staging.size());
                staging.insert(staging.end(), static_cast<const unsigned char*>(a.data),
                               static_cast<const unsigned char*>(a.data) + a.bytes);
            }
            out.vertices = createBuffer();
            glNamedBufferStorage(out.vertices.id(), GLsizeiptr(staging.size()), staging.data(), 0);
            out.indices = createBuffer();
            glNamedBufferStorage(out.indices.id(), GLsizeiptr(p.indices.size() * sizeof(uint32_t)), p.indices.data(), 0);
            out.vao = createVertexArray();
            for (size_t i = 0; i < std::size(attributes); ++i) {
                const Layout& a = attributes[i];
                if (a.bytes == 0) continue;
                const GLsizei stride = GLsizei(a.bytes / p.positions.size());
                glVertexArrayVertexBuffer(out.vao.id(), a.location, out.vertices.id(), GLintptr(offsets[i]), stride);
                glEnableVertexArrayAttrib(out.vao.id(), a.location);
                if (a.integer) glVertexArrayAttribIFormat(out.vao.id(), a.location, a.components, a.type, 0);
                else glVertexArrayAttribFormat(out.vao.id(), a.location, a.components, a.type, GL_FALSE, 0);
                glVertexArrayAttribBinding(out.vao.id(), a.location, a.location);
            }
            glVertexArrayElementBuffer(out.vao.id(), out.indices.id());
            out.indexCount = GLsizei(p.indices.size());
            out.normals = !p.normals.empty();
            out.uv0 = !p.uv0.empty();
            out.tangents = !p.tangents.empty();
            out.skinned = !p.joints.empty();
        }
    }

    auto textureFor = [&](const TextureRef& ref, bool srgb) -> GLuint {
        if (ref.texture < 0 || scene.textures[size_t(ref.texture)].image < 0) return 0;
        auto [it, added] = gpu.textures_.try_emplace({ref.texture, srgb});
        if (added) {
            const GltfTexture& t = scene.textures[size_t(ref.texture)];
            const Sampler* sampler = t.sampler >= 0 ? &scene.samplers[size_t(t.sampler)] : nullptr;
            it->second = detail::uploadTexture(scene.images[size_t(t.image)], sampler, srgb);
        }
        return it->second.id();
    };
    for (const Material& m : scene.materials)
        gpu.materialTextures_.emplace_back(textureFor(m.baseColorTexture, true), textureFor(m.normalTexture, false));

    for (const Skin& skin : scene.skins) {
        GpuSkin& out = gpu.skins_.emplace_back();
        out.joints = skin.joints.size();
        const std::vector<glm::mat4> identity(out.joints, glm::mat4(1.0f));
        for (Buffer* b : {&out.current, &out.previous}) {
            *b = createBuffer();
            glNamedBufferStorage(b->id(), GLsizeiptr(out.joints * sizeof(glm::mat4)), identity.data(), GL_DYNAMIC_STORAGE_BIT);
        }
    }
    return gpu;
}

void GpuScene::updateJoints(const SceneState& state) {
    for (size_t s = 0; s < skins_.size(); ++s) {
        const GLsizeiptr bytes = GLsizeiptr(skins_[s].joints * sizeof(glm::mat4));
        glNamedBufferSubData(skins_[s].current.id(), 0, bytes, state.skin(s).relative.data());
        glNamedBufferSubData(skins_[s].previous.id(), 0, bytes, state.previousSkin(s).relative.data());
    }
}

GLuint GpuScene::texture(int texture, bool srgb) const {
    const auto it = textures_.find({texture, srgb});
    return it == textures_.end() ? 0 : it->second.id();
}

void GpuScene::forEachDraw(const SceneState& state, const std::function<void(const DrawItem&)>& fn) const {
    const Scene& scene = state.scene();
    std::vector<uint32_t> stack(scene.roots.rbegin(), scene.roots.rend());
    while (!stack.empty()) {
        const uint32_t index = stack.back();
        stack.pop_back();
        const Node& node = scene.nodes[index];
        for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back(*it);
        if (node.mesh < 0) continue;
        const auto& primitives = meshes_[size_t(node.mesh)];
        for (size_t p = 0; p < primitives.size(); ++p) {
            const GpuPrimitive& gp = primitives[p];
            const Primitive& cp = scene.meshes[size_t(node.mesh)].primitives[p];
            DrawItem item{.node = index, .mesh = uint32_t(node.mesh), .primitive = uint32_t(p)};
            if (node.skin >= 0 && gp.skinned) {
                item.skin = node.skin;
                item.world = state.skinModel(size_t(node.skin));
                item.previousWorld = state.previousSkinModel(size_t(node.skin));
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kJointsBinding, skins_[size_t(node.skin)].current.id());
                glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPrevJointsBinding, skins_[size_t(node.skin)].previous.id());
            } else {
                item.world = state.world()[index];
                item.previousWorld = state.previousWorld()[index];
            }
            if (cp.material >= 0) {
                item.material = &scene.materials[size_t(cp.material)];
                std::tie(item.baseColorTexture, item.normalTexture) = materialTextures_[size_t(cp.material)];
            }
            item.hasNormals = gp.normals;
            item.hasUv0 = gp.uv0;
            item.hasTangents = gp.tangents;
            item.vertexArray = gp.vao.id();
            item.indexCount = gp.indexCount;
            fn(item);
        }
    }
}

} // namespace rrc::scene
