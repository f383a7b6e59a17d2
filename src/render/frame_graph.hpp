// The frame as a graph of passes. Every pass that draws or computes is added
// with a setup, which declares the named resources it creates, reads and
// writes, and an execute, which issues its GL commands. compile() culls the
// passes whose writes nothing reads (unless they keep(): present, read back),
// finds each transient resource's lifetime and lets transient resources of
// one kind whose lifetimes do not overlap share one GL object (aliasing);
// execute() runs the passes in the order they were added, makes the GL
// objects from a pool kept across frames, issues glMemoryBarrier where a pass
// reads what an earlier pass wrote through storage or image access, and times
// every pass with the frame's PassTimer. Resources are found by name, so any
// module of the frame (a debug view, a system that draws; render/frame/frame_modules.hpp)
// can read what another made. With poisoning on, a texture is filled with a
// marker before the pass that writes it first, so that what a pass leaves
// unwritten shows (`--poison-targets`, the comparisons with forward).
#pragma once

#include <any>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <typeindex>
#include <vector>

#include <glm/glm.hpp>

#include "gfx/allocation_poison.hpp"
#include "gfx/gl.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/pass_timer.hpp"

namespace atrium::render {

// How a pass touches a resource: what decides the barriers between passes.
enum class Access : std::uint8_t {
  Attachment,  // rendered to or depth/stencil-tested as a framebuffer attachment
  Sampled,     // read through a sampler (texelFetch, texture)
  Storage,     // storage buffer or image load/store
  Indirect,    // indirect draw or dispatch commands
  Vertex,      // vertex attributes (a list's instance slots)
  Uniform,     // a uniform block
  Transfer,    // clears, copies, blits, uploads and read-backs
};

struct TextureDesc {
  GLenum format = GL_RGBA8;
  glm::ivec2 size{0};
  int samples = 1;
  bool operator==(const TextureDesc&) const = default;
};

struct BufferDesc {
  std::size_t bytes = 0;
  bool operator==(const BufferDesc&) const = default;
};

// Bytes a texture of `desc` holds (every sample, no mip chain).
[[nodiscard]] std::size_t texture_bytes(const TextureDesc& desc);
// A texture format's short name for listings ("RGBA16F", "D32FS8").
[[nodiscard]] std::string texture_format_name(GLenum format);

struct ResourceId {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::uint32_t index = kNone;
  [[nodiscard]] bool valid() const { return index != kNone; }
  bool operator==(const ResourceId&) const = default;
};

enum class ResourceKind : std::uint8_t { Texture, Buffer };

// What a resource holds, for the debug views (render/debug/debug_views.hpp),
// which pick their visualiser by it: a pass that declares a resource with a
// kind makes it viewable under its name with no other edit. None: nothing to
// look at (light data, scratch, the final output).
enum class ViewKind : std::uint8_t {
  None,
  Color,        // linear HDR colour or summed light: shown exposed and tone-mapped
  Depth,        // depth (a depth-stencil target, or view depth in a float target): log view depth
  GBuffer,      // a G-buffer target: shown through its decoded quantities (position, normal...)
  Counts,       // per-pixel counters (R32UI): a heatmap
  LightBins,    // per-bin light ranges: each pixel's bin's light count (FrameGraph::published<LightBins>)
  ShadowAtlas,  // shadow-map depths
  Identifiers,  // 32-bit identifiers (R32UI, 0 = none): a colour each
};

// A resource a debug view can show (FrameGraph::viewable).
struct ViewableResource {
  std::string name;
  ViewKind kind;
  ResourceId id;
  std::string written_by;  // the first pass that writes it; empty: none (an imported one only read)
};

// What a pass declares about itself while the graph is built.
class PassBuilder {
 public:
  // A transient resource this pass writes first; made by the graph, valid
  // from this pass to the last pass that reads it.
  ResourceId create(const std::string& name, const TextureDesc& desc, ViewKind view = ViewKind::None);
  ResourceId create(const std::string& name, const BufferDesc& desc, ViewKind view = ViewKind::None);
  ResourceId read(ResourceId resource, Access access);
  ResourceId write(ResourceId resource, Access access);
  // Reads a texture that the pass's shaders sample at a shared texture unit
  // (render/binding_slots.hpp): the graph binds it there before the pass runs.
  ResourceId sample_at(ResourceId texture, unsigned unit);
  // By name (any module's resource); invalid when none has that name.
  [[nodiscard]] ResourceId find(const std::string& name) const;

  // The pass has effects the graph cannot see (presenting, a read-back, state
  // a later frame uses): it is never culled.
  void keep();

 private:
  friend class FrameGraph;
  PassBuilder(class FrameGraph& graph, std::uint32_t pass) : graph_(graph), pass_(pass) {}
  FrameGraph& graph_;
  std::uint32_t pass_;
};

// What a pass sees while it runs: the GL objects behind its resources.
class PassResources {
 public:
  [[nodiscard]] GLuint texture(ResourceId resource) const;
  [[nodiscard]] GLuint buffer(ResourceId resource) const;
  // What a texture resource was declared as (format, size, samples).
  [[nodiscard]] const TextureDesc& texture_desc(ResourceId resource) const;
  // A framebuffer with these textures as colour attachments 0.. and `depth`
  // (depth-stencil or depth, by its format; invalid: none), made once and kept
  // while the textures live.
  [[nodiscard]] GLuint framebuffer(std::span<const ResourceId> colors, ResourceId depth = {}) const;
  [[nodiscard]] GLuint framebuffer(std::initializer_list<ResourceId> colors, ResourceId depth = {}) const {
    return framebuffer(std::span<const ResourceId>(colors.begin(), colors.size()), depth);
  }

 private:
  friend class FrameGraph;
  explicit PassResources(const FrameGraph& graph) : graph_(graph) {}
  const FrameGraph& graph_;
};

// Render-target memory of one compiled frame.
struct GraphMemory {
  std::size_t transient_bytes = 0;  // every transient resource in a GL object of its own
  std::size_t aliased_bytes = 0;    // as allocated, resources that never live together sharing objects
  std::size_t imported_bytes = 0;   // long-lived targets owned outside the graph (depth, HDR colour, output, shadows...)
};

// One resource a compiled frame uses (info --memory): what it is and what it holds.
struct ResourceUse {
  std::string name;
  ResourceKind kind;
  bool imported;            // long-lived, owned outside the graph; else transient
  std::size_t bytes;        // as declared: every sample, no mip chain
  std::string description;  // "RGBA16F 1280x720 x4 samples", "buffer"
};

// One pass as compiled: for tests, the overlay and docs.
struct CompiledPass {
  std::string name;
  bool culled = false;
  GLbitfield barriers = 0;  // glMemoryBarrier bits issued before it
};

class FrameGraph {
 public:
  using Setup = std::function<void(PassBuilder&)>;
  using Execute = std::function<void(const PassResources&)>;

  FrameGraph();
  ~FrameGraph();
  FrameGraph(const FrameGraph&) = delete;
  FrameGraph& operator=(const FrameGraph&) = delete;

  // Starts a new frame's graph; the GL objects of transient resources stay
  // pooled for the next frames.
  void reset();

  // A long-lived GL object owned elsewhere, under `name`. Its owner calls
  // forget_imports() when it remakes one (a resize), so that framebuffers
  // cached on the old objects go.
  void forget_imports();
  // A long-lived GL object owned elsewhere, under `name`.
  ResourceId import_texture(const std::string& name, GLuint texture, const TextureDesc& desc, ViewKind view = ViewKind::None);
  ResourceId import_buffer(const std::string& name, GLuint buffer, const BufferDesc& desc, ViewKind view = ViewKind::None);

  // Adds a pass; `setup` runs now, `execute` when the graph executes. Untimed
  // passes (timed = false) are for work too small to be worth a line.
  void add_pass(const std::string& name, const Setup& setup, Execute execute, bool timed = true);

  [[nodiscard]] ResourceId find(const std::string& name) const;
  // Every resource declared with a ViewKind, in the order declared, with the
  // pass that writes it (for listings).
  [[nodiscard]] std::vector<ViewableResource> viewable() const;
  // A resource's ViewKind (None for an invalid id), and the first resource
  // declared with `kind` (invalid when none): the lookups a frame's debug
  // view makes, without building the listing.
  [[nodiscard]] ViewKind view_kind(ResourceId resource) const;
  [[nodiscard]] ResourceId first_of(ViewKind kind) const;

  // What a module tells the frame's later passes beyond its resources
  // (how its light lists map pixels to bins, say): one value per type, kept
  // until reset(). The reader needs no hook into the writer.
  template <typename T>
  void publish(T value) { board_[std::type_index(typeid(T))] = std::move(value); }
  template <typename T>
  [[nodiscard]] const T* published() const {
    const auto it = board_.find(std::type_index(typeid(T)));
    return it == board_.end() ? nullptr : std::any_cast<T>(&it->second);
  }

  // Culls, finds lifetimes and plans which transient resources share objects.
  void compile();
  // Runs the passes that were not culled, each timed by `timer` when given.
  void execute(gfx::PassTimer* timer);

  // On: before a pass that writes a texture without reading it, and before
  // any earlier pass used it this frame, execute() fills the texture with
  // kPoison (colour), kPoisonIdentifier (integer formats) or kPoisonDepth,
  // untimed. Transient objects hold another resource's texels from an
  // earlier frame and long-lived ones the last frame's: a pass that leaves a
  // texel unwritten is a bug these hide, and a marker shows. A pass that
  // keeps a long-lived texture's texels (a cached shadow map) declares a read.
  void set_poison(bool on) { poison_ = on; }
  static constexpr glm::vec4 kPoison{64.0f, 0.0f, 64.0f, 1.0f};  // bright magenta; saturates unorm targets
  static constexpr std::uint32_t kPoisonIdentifier = gfx::kPoisonWord;  // as in the tests' new buffers
  static constexpr float kPoisonDepth = 0.5f;

  [[nodiscard]] const std::vector<CompiledPass>& passes() const { return compiled_; }
  [[nodiscard]] GraphMemory memory() const { return memory_; }
  // Every resource a pass that runs uses, in the order declared.
  [[nodiscard]] std::vector<ResourceUse> used_resources() const;
  // The objects the pool holds (transient resources made in earlier frames).
  [[nodiscard]] std::size_t pooled_objects() const;

 private:
  friend class PassBuilder;
  friend class PassResources;

  struct Use {
    std::uint32_t resource;
    Access access;
    bool write;
  };
  struct Pass {
    std::string name;
    Execute execute;
    bool timed = true;
    bool kept = false;
    std::vector<Use> uses;
    std::vector<std::pair<std::uint32_t, unsigned>> units;  // sample_at's textures and units
  };
  struct Resource {
    std::string name;
    ResourceKind kind = ResourceKind::Texture;
    TextureDesc texture;
    BufferDesc buffer;
    bool imported = false;
    ViewKind view = ViewKind::None;
    GLuint object = 0;              // imported: given; transient: set by execute
    std::uint32_t first = 0, last = 0;  // passes that first and last use it
    bool used = false;
    std::uint32_t slot = 0;         // transient: the shared object it lives in
  };
  struct Slot {
    ResourceKind kind;
    TextureDesc texture;
    BufferDesc buffer;
    std::uint32_t free_after = 0;  // the last pass of its latest resource
  };

  std::uint32_t add_resource(Resource resource);
  ResourceId create(std::uint32_t pass, Resource resource, Access first_write);
  void use(std::uint32_t pass, ResourceId resource, Access access, bool write);
  GLuint framebuffer(std::span<const ResourceId> colors, ResourceId depth) const;
  void poison_first_writes(std::uint32_t pass) const;

  std::vector<Pass> passes_;
  std::vector<Resource> resources_;
  std::map<std::string, std::uint32_t> by_name_;
  std::map<std::type_index, std::any> board_;
  std::vector<Slot> slots_;
  std::vector<CompiledPass> compiled_;
  GraphMemory memory_;
  bool poison_ = false;

  // GL objects kept across frames: per description, a list; a frame takes
  // them in order, and those no frame took for a while are released.
  struct Pool;
  std::unique_ptr<Pool> pool_;
};

}  // namespace atrium::render
