#include "gl/entity_pass.h"

#include <algorithm>
#include <cmath>

#include "gl/frame_state.h"
#include "gl/texture_units.h"

namespace ig::gl {
namespace {

constexpr GLuint kVertexFloats = 8;  // position, normal, texture coordinate
// Per instance: the node's mat4 (locations 3-6) and the alpha (location 7).
struct InstanceRecord {
  glm::mat4 node_to_eye;
  glm::vec4 alpha;  // x: alpha; 16-byte records
};

GLenum wrap_of(models::TextureWrap w) {
  switch (w) {
    case models::TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case models::TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case models::TextureWrap::Repeat: break;
  }
  return GL_REPEAT;
}

Texture upload_image(const models::Image& image, const models::Material* user) {
  Texture t = create_texture(GL_TEXTURE_2D);
  const int levels = 1 + int(std::floor(std::log2(double(std::max(image.width, image.height)))));
  glTextureStorage2D(t.id(), levels, GL_RGBA8, image.width, image.height);
  glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  count_upload(image.rgba.size());
  glGenerateTextureMipmap(t.id());
  glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, user ? GLint(wrap_of(user->wrap_s)) : GL_REPEAT);
  glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, user ? GLint(wrap_of(user->wrap_t)) : GL_REPEAT);
  return t;
}

}  // namespace

EntityMesh::EntityMesh(const models::Model& model) : vao_(create_vertex_array()), node_count_(model.nodes.size()) {
  std::vector<float> vertices;
  std::vector<std::uint32_t> indices;
  // Where each mesh's primitives start: (first index, base vertex).
  std::vector<std::vector<std::pair<std::size_t, GLint>>> starts(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    for (const models::Primitive& p : model.meshes[m].primitives) {
      starts[m].push_back({indices.size(), GLint(vertices.size() / kVertexFloats)});
      for (std::size_t v = 0; v < p.positions.size(); ++v) {
        const glm::vec2 uv = v < p.texcoords.size() ? p.texcoords[v] : glm::vec2(0.0f);
        const glm::vec3& n = p.normals[v];
        vertices.insert(vertices.end(), {p.positions[v].x, p.positions[v].y, p.positions[v].z, n.x, n.y, n.z, uv.x, uv.y});
      }
      indices.insert(indices.end(), p.indices.begin(), p.indices.end());
    }
  }
  vertices_ = create_buffer(vertices);
  indices_ = create_buffer(indices);
  count_upload(vertices.size() * sizeof(float) + indices.size() * sizeof(std::uint32_t));
  glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, kVertexFloats * sizeof(float));
  glVertexArrayElementBuffer(vao_.id(), indices_.id());
  vertex_attrib_float(vao_, 0, 3, GL_FLOAT, 0, 0);
  vertex_attrib_float(vao_, 1, 3, GL_FLOAT, 3 * sizeof(float), 0);
  vertex_attrib_float(vao_, 2, 2, GL_FLOAT, 6 * sizeof(float), 0);
  for (GLuint k = 0; k < 4; ++k) vertex_attrib_float(vao_, 3 + k, 4, GL_FLOAT, k * sizeof(glm::vec4), 1);
  vertex_attrib_float(vao_, 7, 1, GL_FLOAT, sizeof(glm::mat4), 1);
  glVertexArrayBindingDivisor(vao_.id(), 1, 1);

  // Each image uploaded once, with the wrap of the first material using it.
  std::vector<const models::Material*> user(model.images.size(), nullptr);
  for (const auto& mat : model.materials)
    if (mat.base_color_image >= 0 && std::size_t(mat.base_color_image) < user.size() && !user[mat.base_color_image])
      user[mat.base_color_image] = &mat;
  for (std::size_t i = 0; i < model.images.size(); ++i) textures_.push_back(upload_image(model.images[i], user[i]));

  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    const int mesh = model.nodes[n].mesh;
    if (mesh < 0) continue;
    const auto& prims = model.meshes[std::size_t(mesh)].primitives;
    for (std::size_t k = 0; k < prims.size(); ++k) {
      Part part;
      part.node = int(n);
      part.index_count = GLsizei(prims[k].indices.size());
      part.first_index = starts[std::size_t(mesh)][k].first;
      part.base_vertex = starts[std::size_t(mesh)][k].second;
      if (prims[k].material >= 0) {
        const models::Material& mat = model.materials[std::size_t(prims[k].material)];
        part.base_color = mat.base_color;
        part.texture = prims[k].texcoords.empty() ? -1 : mat.base_color_image;
        part.blend = mat.alpha_mode == models::AlphaMode::Blend;
        part.alpha_cutoff = mat.alpha_mode == models::AlphaMode::Mask ? mat.alpha_cutoff : -1.0f;
        part.double_sided = mat.double_sided;
        part.unlit = mat.unlit;
      }
      triangles_ += std::uint64_t(part.index_count / 3);
      parts_.push_back(part);
    }
  }
}

EntityPass::EntityPass(const std::string& shader_dir)
    : program_(shader_dir, "entity.vert", std::vector<std::string>{"entity.frag", "fog.frag"}),
      instances_(create_buffer()) {}

void EntityPass::draw_part(const PartDraw& d) {
  const EntityMesh& mesh = *d.mesh;
  const EntityMesh::Part& part = *d.part;
  glBindVertexArray(mesh.vao_.id());
  glVertexArrayVertexBuffer(mesh.vao_.id(), 1, instances_.id(), GLintptr(d.first_record * sizeof(InstanceRecord)),
                            GLsizei(sizeof(InstanceRecord)));
  program_.set("u_base_color", part.base_color);
  program_.set("u_has_texture", part.texture >= 0 ? 1 : 0);
  if (part.texture >= 0)
    glBindTextureUnit(unit(TextureUnit::kEntityBaseColor), mesh.textures_[std::size_t(part.texture)].id());
  program_.set("u_alpha_cutoff", part.alpha_cutoff);
  program_.set("u_unlit", part.unlit ? 1 : 0);
  if (part.double_sided) glDisable(GL_CULL_FACE);
  else glEnable(GL_CULL_FACE);
  glDrawElementsInstancedBaseVertex(GL_TRIANGLES, part.index_count, GL_UNSIGNED_INT,
                                    reinterpret_cast<const void*>(part.first_index * sizeof(std::uint32_t)),
                                    GLsizei(d.count), part.base_vertex);
  count_draw();
}

void EntityPass::draw(const RenderTarget& target, const std::vector<Batch>& batches, const EntityLighting& light,
                      PassRecorder& recorder) {
  if (batches.empty()) return;
  // Every part's instance records (its node's matrix, the alpha) in one
  // buffer, uploaded once; opaque parts drawn first, translucent ones after.
  std::vector<InstanceRecord> records;
  std::vector<PartDraw> opaque, translucent;
  for (const Batch& b : batches) {
    for (const auto& part : b.mesh->parts_) {
      const PartDraw d{b.mesh, &part, records.size(), b.instances->size()};
      for (const auto& inst : *b.instances)
        records.push_back({inst.node_to_eye[std::size_t(part.node)], glm::vec4(inst.alpha, 0.0f, 0.0f, 0.0f)});
      (part.blend ? translucent : opaque).push_back(d);
    }
  }
  const std::size_t bytes = records.size() * sizeof(InstanceRecord);
  if (bytes > capacity_) {
    capacity_ = std::max(bytes, 2 * capacity_);
    glNamedBufferData(instances_.id(), GLsizeiptr(capacity_), nullptr, GL_STREAM_DRAW);
  }
  glNamedBufferSubData(instances_.id(), 0, GLsizeiptr(bytes), records.data());
  count_upload(bytes);

  target.bind_color_only();
  recorder.begin("entities");
  use_frame_depth_test();
  const GLboolean culled = glIsEnabled(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // alpha keeps the terrain's coverage code
  program_.use();
  program_.set("u_view_proj", light.view_proj);
  program_.set("u_earth_radius_m", light.earth_radius_m);
  program_.set("u_sun_dir", light.sun_dir);
  program_.set("u_light_color", light.light_color);
  program_.set("u_ambient", light.ambient);
  program_.set("u_fog_color", light.fog_color);
  program_.set("u_fog_k", light.fog_k);
  program_.set("u_base_texture", unit(TextureUnit::kEntityBaseColor));
  for (const PartDraw& d : opaque) draw_part(d);
  // Translucent parts over everything opaque, without writing depth.
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  for (const PartDraw& d : translucent) draw_part(d);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glBindVertexArray(0);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (culled) glEnable(GL_CULL_FACE);
  else glDisable(GL_CULL_FACE);
  recorder.end();
}

}  // namespace ig::gl
