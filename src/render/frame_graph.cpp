#include "render/frame_graph.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace atrium::render {
namespace {

// Frames a pooled object may go untaken before it is released (a debug view
// switched off, a size changed): a few, so that toggles do not churn.
constexpr int kIdleFramesKept = 3;

// What a format's texels hold: which clears and attachments it takes.
enum class Texels : std::uint8_t { Color, Integer, Depth, DepthStencil, Stencil };

// Every texture format a frame target is made in: its name for listings, its
// bytes per texel (per sample) and what its texels hold.
struct FormatRow {
  GLenum format;
  const char* name;
  std::size_t bytes;
  Texels texels = Texels::Color;
};
constexpr FormatRow kFormats[] = {
    {GL_R8, "R8", 1},
    {GL_STENCIL_INDEX8, "S8", 1, Texels::Stencil},
    {GL_RG8, "RG8", 2},
    {GL_R16F, "R16F", 2},
    {GL_R16UI, "R16UI", 2, Texels::Integer},
    {GL_RGBA8, "RGBA8", 4},
    {GL_SRGB8_ALPHA8, "SRGB8_A8", 4},
    {GL_R32F, "R32F", 4},
    {GL_R32UI, "R32UI", 4, Texels::Integer},
    {GL_RG16F, "RG16F", 4},
    {GL_RGB10_A2, "RGB10_A2", 4},
    {GL_R11F_G11F_B10F, "R11F_G11F_B10F", 4},
    {GL_DEPTH24_STENCIL8, "D24S8", 4, Texels::DepthStencil},
    {GL_DEPTH_COMPONENT32F, "D32F", 4, Texels::Depth},
    {GL_RG16UI, "RG16UI", 4, Texels::Integer},
    {GL_DEPTH32F_STENCIL8, "D32FS8", 8, Texels::DepthStencil},  // 32-bit depth, 8-bit stencil, padded as drivers store it
    {GL_RGBA16F, "RGBA16F", 8},
    {GL_RGBA16, "RGBA16", 8},
    {GL_RG32F, "RG32F", 8},
    {GL_RG32UI, "RG32UI", 8, Texels::Integer},
    {GL_RGBA16UI, "RGBA16UI", 8, Texels::Integer},
    {GL_RGBA32F, "RGBA32F", 16},
    {GL_RGBA32UI, "RGBA32UI", 16, Texels::Integer},
};

const FormatRow& format_row(GLenum format) {
  for (const FormatRow& row : kFormats) {
    if (row.format == format) return row;
  }
  throw std::logic_error("frame graph: no size known for texture format " + std::to_string(format));
}

std::size_t bytes_per_texel(GLenum format) { return format_row(format).bytes; }

bool is_depth(GLenum format) {
  const Texels texels = format_row(format).texels;
  return texels == Texels::Depth || texels == Texels::DepthStencil;
}

bool has_stencil(GLenum format) { return format_row(format).texels == Texels::DepthStencil; }

// The barrier a use needs after a write through storage or image access.
GLbitfield barrier_for(Access access, ResourceKind kind) {
  switch (access) {
    case Access::Attachment: return GL_FRAMEBUFFER_BARRIER_BIT;
    case Access::Sampled: return GL_TEXTURE_FETCH_BARRIER_BIT;
    case Access::Storage: return kind == ResourceKind::Buffer ? GL_SHADER_STORAGE_BARRIER_BIT : GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
    case Access::Indirect: return GL_COMMAND_BARRIER_BIT;
    case Access::Vertex: return GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT;
    case Access::Uniform: return GL_UNIFORM_BARRIER_BIT;
    // Texture transfers go through framebuffers too (blits, clears, glReadPixels).
    case Access::Transfer:
      return kind == ResourceKind::Buffer ? GL_BUFFER_UPDATE_BARRIER_BIT : GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT;
  }
  return 0;
}

}  // namespace

std::size_t texture_bytes(const TextureDesc& desc) {
  return static_cast<std::size_t>(std::max(desc.size.x, 0)) * static_cast<std::size_t>(std::max(desc.size.y, 0)) *
         static_cast<std::size_t>(std::max(desc.samples, 1)) * bytes_per_texel(desc.format);
}

struct FrameGraph::Pool {
  struct PooledTexture {
    TextureDesc desc;
    gfx::Texture object;
    int idle = 0;
    bool taken = false;
  };
  struct PooledBuffer {
    BufferDesc desc;
    gfx::Buffer object;
    int idle = 0;
    bool taken = false;
  };
  std::vector<PooledTexture> textures;
  std::vector<PooledBuffer> buffers;
  std::map<std::vector<GLuint>, gfx::Framebuffer> framebuffers;  // by attachments: colours..., depth (0: none)

  GLuint take(const TextureDesc& desc) {
    for (PooledTexture& t : textures) {
      if (!t.taken && t.desc == desc) {
        t.taken = true;
        return t.object.id();
      }
    }
    textures.push_back({desc, gfx::create_render_target(desc.format, desc.size.x, desc.size.y, desc.samples), 0, true});
    return textures.back().object.id();
  }

  GLuint take(const BufferDesc& desc) {
    for (PooledBuffer& b : buffers) {
      if (!b.taken && b.desc == desc) {
        b.taken = true;
        return b.object.id();
      }
    }
    gfx::Buffer buffer = gfx::create_buffer();
    glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(desc.bytes, 4)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    buffers.push_back({desc, std::move(buffer), 0, true});
    return buffers.back().object.id();
  }

  // Releases what no frame took for a while, with the framebuffers on it.
  void end_frame() {
    std::vector<GLuint> released;
    std::erase_if(textures, [&](PooledTexture& t) {
      t.idle = t.taken ? 0 : t.idle + 1;
      t.taken = false;
      if (t.idle <= kIdleFramesKept) return false;
      released.push_back(t.object.id());
      return true;
    });
    std::erase_if(buffers, [](PooledBuffer& b) {
      b.idle = b.taken ? 0 : b.idle + 1;
      b.taken = false;
      return b.idle > kIdleFramesKept;
    });
    std::erase_if(framebuffers, [&](const auto& entry) {
      return std::any_of(entry.first.begin(), entry.first.end(),
                         [&](GLuint id) { return id != 0 && std::find(released.begin(), released.end(), id) != released.end(); });
    });
  }
};

ResourceId PassBuilder::create(const std::string& name, const TextureDesc& desc, ViewKind view) {
  return graph_.create(pass_, {.name = name, .kind = ResourceKind::Texture, .texture = desc, .buffer = {}, .view = view}, Access::Attachment);
}

ResourceId PassBuilder::create(const std::string& name, const BufferDesc& desc, ViewKind view) {
  return graph_.create(pass_, {.name = name, .kind = ResourceKind::Buffer, .texture = {}, .buffer = desc, .view = view}, Access::Transfer);
}

ResourceId PassBuilder::read(ResourceId resource, Access access) {
  graph_.use(pass_, resource, access, false);
  return resource;
}

ResourceId PassBuilder::write(ResourceId resource, Access access) {
  graph_.use(pass_, resource, access, true);
  return resource;
}

ResourceId PassBuilder::sample_at(ResourceId texture, unsigned unit) {
  graph_.use(pass_, texture, Access::Sampled, false);
  graph_.passes_[pass_].units.emplace_back(texture.index, unit);
  return texture;
}

ResourceId PassBuilder::find(const std::string& name) const { return graph_.find(name); }

void PassBuilder::keep() { graph_.passes_[pass_].kept = true; }

GLuint PassResources::texture(ResourceId resource) const {
  const auto& r = graph_.resources_.at(resource.index);
  if (r.kind != ResourceKind::Texture) throw std::logic_error("frame graph: '" + r.name + "' is not a texture");
  return r.object;
}

const TextureDesc& PassResources::texture_desc(ResourceId resource) const {
  const auto& r = graph_.resources_.at(resource.index);
  if (r.kind != ResourceKind::Texture) throw std::logic_error("frame graph: '" + r.name + "' is not a texture");
  return r.texture;
}

GLuint PassResources::buffer(ResourceId resource) const {
  const auto& r = graph_.resources_.at(resource.index);
  if (r.kind != ResourceKind::Buffer) throw std::logic_error("frame graph: '" + r.name + "' is not a buffer");
  return r.object;
}


GLuint PassResources::framebuffer(std::span<const ResourceId> colors, ResourceId depth) const { return graph_.framebuffer(colors, depth); }

FrameGraph::FrameGraph() : pool_(std::make_unique<Pool>()) {}
FrameGraph::~FrameGraph() = default;

void FrameGraph::reset() {
  passes_.clear();
  resources_.clear();
  by_name_.clear();
  board_.clear();
  slots_.clear();
  compiled_.clear();
  memory_ = {};
}

void FrameGraph::forget_imports() { pool_->framebuffers.clear(); }

std::uint32_t FrameGraph::add_resource(Resource resource) {
  if (by_name_.contains(resource.name)) throw std::logic_error("frame graph: two resources are named '" + resource.name + "'");
  const auto index = static_cast<std::uint32_t>(resources_.size());
  by_name_.emplace(resource.name, index);
  resources_.push_back(std::move(resource));
  return index;
}

ResourceId FrameGraph::create(std::uint32_t pass, Resource resource, Access first_write) {
  const ResourceId id{add_resource(std::move(resource))};
  use(pass, id, first_write, true);
  return id;
}

ResourceId FrameGraph::import_texture(const std::string& name, GLuint texture, const TextureDesc& desc, ViewKind view) {
  return {add_resource({.name = name, .kind = ResourceKind::Texture, .texture = desc, .buffer = {}, .imported = true, .view = view, .object = texture})};
}

ResourceId FrameGraph::import_buffer(const std::string& name, GLuint buffer, const BufferDesc& desc, ViewKind view) {
  return {add_resource({.name = name, .kind = ResourceKind::Buffer, .texture = {}, .buffer = desc, .imported = true, .view = view, .object = buffer})};
}

void FrameGraph::use(std::uint32_t pass, ResourceId resource, Access access, bool write) {
  if (!resource.valid() || resource.index >= resources_.size()) {
    throw std::logic_error("frame graph: pass '" + passes_[pass].name + "' uses a resource that was never declared");
  }
  const Resource& r = resources_[resource.index];
  if (!write && !r.imported) {
    const bool written = std::any_of(passes_.begin(), passes_.begin() + pass, [&](const Pass& p) {
      return std::any_of(p.uses.begin(), p.uses.end(), [&](const Use& u) { return u.write && u.resource == resource.index; });
    });
    if (!written) throw std::logic_error("frame graph: pass '" + passes_[pass].name + "' reads '" + r.name + "' before any pass writes it");
  }
  passes_[pass].uses.push_back({resource.index, access, write});
}

void FrameGraph::add_pass(const std::string& name, const Setup& setup, Execute execute, bool timed) {
  const auto index = static_cast<std::uint32_t>(passes_.size());
  passes_.push_back({name, std::move(execute), timed, false, {}, {}});
  PassBuilder builder(*this, index);
  if (setup) setup(builder);
}

ResourceId FrameGraph::find(const std::string& name) const {
  const auto it = by_name_.find(name);
  return it == by_name_.end() ? ResourceId{} : ResourceId{it->second};
}

std::string texture_format_name(GLenum format) { return format_row(format).name; }

std::vector<ResourceUse> FrameGraph::used_resources() const {
  std::vector<ResourceUse> used;
  for (const Resource& r : resources_) {
    if (!r.used) continue;
    ResourceUse use{r.name, r.kind, r.imported, r.kind == ResourceKind::Texture ? texture_bytes(r.texture) : r.buffer.bytes, {}};
    if (r.kind == ResourceKind::Texture) {
      use.description = texture_format_name(r.texture.format) + " " + std::to_string(r.texture.size.x) + "x" + std::to_string(r.texture.size.y);
      if (r.texture.samples > 1) use.description += " x" + std::to_string(r.texture.samples) + " samples";
    } else {
      use.description = "buffer";
    }
    used.push_back(std::move(use));
  }
  return used;
}

std::vector<ViewableResource> FrameGraph::viewable() const {
  std::vector<ViewableResource> resources;
  for (std::uint32_t i = 0; i < resources_.size(); ++i) {
    if (resources_[i].view == ViewKind::None) continue;
    std::string writer;
    for (const Pass& pass : passes_) {
      if (std::any_of(pass.uses.begin(), pass.uses.end(), [&](const Use& u) { return u.write && u.resource == i; })) {
        writer = pass.name;
        break;
      }
    }
    resources.push_back({resources_[i].name, resources_[i].view, {i}, writer});
  }
  return resources;
}

void FrameGraph::compile() {
  const std::size_t count = passes_.size();
  // Culling, from the last pass back: a pass is needed when it keeps itself,
  // writes a long-lived (imported) resource, or writes what a needed pass reads.
  std::vector<bool> needed(count, false), resource_needed(resources_.size(), false);
  for (std::size_t p = count; p-- > 0;) {
    const Pass& pass = passes_[p];
    bool need = pass.kept;
    for (const Use& u : pass.uses) need = need || (u.write && (resources_[u.resource].imported || resource_needed[u.resource]));
    if (!need) continue;
    needed[p] = true;
    for (const Use& u : pass.uses) {
      if (!u.write) resource_needed[u.resource] = true;
    }
  }
  // Lifetimes over the passes that run.
  for (Resource& r : resources_) r.used = false;
  for (std::uint32_t p = 0; p < count; ++p) {
    if (!needed[p]) continue;
    for (const Use& u : passes_[p].uses) {
      Resource& r = resources_[u.resource];
      if (!r.used) r.first = p;
      r.used = true;
      r.last = p;
    }
  }
  // Transient resources share an object with an earlier one of the same kind
  // and description whose last pass came before their first.
  slots_.clear();
  memory_ = {};
  std::vector<std::uint32_t> order;
  for (std::uint32_t i = 0; i < resources_.size(); ++i) {
    if (resources_[i].used && !resources_[i].imported) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return resources_[a].first < resources_[b].first; });
  for (const std::uint32_t i : order) {
    Resource& r = resources_[i];
    const std::size_t bytes = r.kind == ResourceKind::Texture ? texture_bytes(r.texture) : r.buffer.bytes;
    memory_.transient_bytes += bytes;
    auto fits = [&](const Slot& s) {
      return s.kind == r.kind && s.free_after < r.first && (r.kind == ResourceKind::Texture ? s.texture == r.texture : s.buffer == r.buffer);
    };
    const auto slot = std::find_if(slots_.begin(), slots_.end(), fits);
    if (slot != slots_.end()) {
      slot->free_after = r.last;
      r.slot = static_cast<std::uint32_t>(slot - slots_.begin());
    } else {
      slots_.push_back({r.kind, r.texture, r.buffer, r.last});
      r.slot = static_cast<std::uint32_t>(slots_.size() - 1);
      memory_.aliased_bytes += bytes;
    }
  }
  for (const Resource& r : resources_) {
    if (r.imported && r.used) memory_.imported_bytes += r.kind == ResourceKind::Texture ? texture_bytes(r.texture) : r.buffer.bytes;
  }
  // Barriers: a use after a write through storage or image access waits for it.
  compiled_.assign(count, {});
  std::vector<bool> storage_written(resources_.size(), false);
  for (std::uint32_t p = 0; p < count; ++p) {
    compiled_[p].name = passes_[p].name;
    compiled_[p].culled = !needed[p];
    if (!needed[p]) continue;
    for (const Use& u : passes_[p].uses) {
      if (storage_written[u.resource]) compiled_[p].barriers |= barrier_for(u.access, resources_[u.resource].kind);
    }
    for (const Use& u : passes_[p].uses) {
      if (!u.write) continue;
      storage_written[u.resource] = u.access == Access::Storage;
    }
  }
}

void FrameGraph::execute(gfx::PassTimer* timer) {
  // reset() empties the compiled passes: a graph not compiled since is now.
  if (compiled_.size() != passes_.size()) compile();
  // Each slot takes one pooled object; its resources all point at it.
  std::vector<GLuint> objects(slots_.size());
  for (std::size_t s = 0; s < slots_.size(); ++s) {
    objects[s] = slots_[s].kind == ResourceKind::Texture ? pool_->take(slots_[s].texture) : pool_->take(slots_[s].buffer);
  }
  for (Resource& r : resources_) {
    if (r.used && !r.imported) r.object = objects[r.slot];
  }
  // A pass may throw (a frame the driver cannot hold): the pool still ends
  // the frame, so that its objects are taken again by the next one.
  struct EndFrame {
    Pool& pool;
    ~EndFrame() { pool.end_frame(); }
  } end_frame{*pool_};
  for (std::size_t p = 0; p < passes_.size(); ++p) {
    if (compiled_[p].culled) continue;
    if (compiled_[p].barriers) glMemoryBarrier(compiled_[p].barriers);
    Pass& pass = passes_[p];
    if (!pass.execute) continue;
    if (poison_) poison_first_writes(static_cast<std::uint32_t>(p));
    const PassResources resources(*this);
    for (const auto& [resource, unit] : pass.units) glBindTextureUnit(unit, resources.texture({resource}));
    if (timer && pass.timed) {
      const auto scope = timer->scope(pass.name);
      pass.execute(resources);
    } else {
      pass.execute(resources);
    }
  }
}

void FrameGraph::poison_first_writes(std::uint32_t pass) const {
  const std::vector<Use>& uses = passes_[pass].uses;
  for (std::size_t i = 0; i < uses.size(); ++i) {
    const Resource& r = resources_[uses[i].resource];
    if (r.kind != ResourceKind::Texture || r.first != pass) continue;
    // Once per resource, and not when the pass also reads it.
    const auto same = [&](const Use& u) { return u.resource == uses[i].resource; };
    if (std::any_of(uses.begin(), uses.begin() + static_cast<std::ptrdiff_t>(i), same)) continue;
    if (std::any_of(uses.begin(), uses.end(), [&](const Use& u) { return same(u) && !u.write; })) continue;
    switch (format_row(r.texture.format).texels) {
      case Texels::DepthStencil: {
        // GL_FLOAT_32_UNSIGNED_INT_24_8_REV: the depth as a float, then the stencil in the low byte.
        const struct { float depth; std::uint32_t stencil; } texel{kPoisonDepth, 0x5au};
        glClearTexImage(r.object, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, &texel);
        break;
      }
      case Texels::Depth: glClearTexImage(r.object, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &kPoisonDepth); break;
      case Texels::Stencil: {
        const std::uint8_t stencil = 0x5au;
        glClearTexImage(r.object, 0, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &stencil);
        break;
      }
      case Texels::Integer: {
        const std::uint32_t texel[4] = {kPoisonIdentifier, kPoisonIdentifier, kPoisonIdentifier, kPoisonIdentifier};
        glClearTexImage(r.object, 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT, texel);
        break;
      }
      case Texels::Color: glClearTexImage(r.object, 0, GL_RGBA, GL_FLOAT, &kPoison.x); break;
    }
  }
}

std::size_t FrameGraph::pooled_objects() const { return pool_->textures.size() + pool_->buffers.size(); }

ViewKind FrameGraph::view_kind(ResourceId resource) const {
  return resource.valid() && resource.index < resources_.size() ? resources_[resource.index].view : ViewKind::None;
}

ResourceId FrameGraph::first_of(ViewKind kind) const {
  for (std::uint32_t i = 0; i < resources_.size(); ++i) {
    if (resources_[i].view == kind) return {i};
  }
  return {};
}

GLuint FrameGraph::framebuffer(std::span<const ResourceId> colors, ResourceId depth) const {
  std::vector<GLuint> key;
  for (const ResourceId c : colors) key.push_back(resources_.at(c.index).object);
  key.push_back(depth.valid() ? resources_.at(depth.index).object : 0);
  // Kept until the pool releases one of its textures, or an owner remakes an
  // imported one (forget_imports).
  const auto it = pool_->framebuffers.find(key);
  if (it != pool_->framebuffers.end()) return it->second.id();
  gfx::Framebuffer framebuffer = gfx::create_framebuffer();
  std::vector<GLenum> buffers;
  for (std::size_t i = 0; i + 1 < key.size(); ++i) {
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i), key[i], 0);
    buffers.push_back(GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i));
  }
  if (depth.valid()) {
    const GLenum format = resources_.at(depth.index).texture.format;
    if (!is_depth(format)) throw std::logic_error("frame graph: '" + resources_.at(depth.index).name + "' is not a depth target");
    glNamedFramebufferTexture(framebuffer.id(), has_stencil(format) ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, key.back(), 0);
  }
  if (buffers.empty()) glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
  else glNamedFramebufferDrawBuffers(framebuffer.id(), static_cast<GLsizei>(buffers.size()), buffers.data());
  gfx::require_complete(framebuffer.id(), "frame graph");
  const GLuint id = framebuffer.id();
  pool_->framebuffers.emplace(std::move(key), std::move(framebuffer));
  return id;
}

}  // namespace atrium::render
