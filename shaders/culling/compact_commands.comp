#version 450 core
// Reads one occlusion-culling phase's commands (occlusion_cull.comp: those it
// leaves out have an instance count of 0) and writes them packed: each
// batch's drawn commands at the front of its range, in their order (front to
// back), and how many there are, for glMultiDrawElementsIndirectCount (GL 4.6
// or ARB_indirect_parameters), so that the GPU's front end skips what was left
// out. One work group per batch scans its range 64 commands at a time.
layout(local_size_x = 64) in;

struct DrawCommand {
  uint count;
  uint instance_count;
  uint first_index;
  int base_vertex;
  uint base_instance;
};

layout(std430, binding = 17) readonly buffer In { DrawCommand u_in[]; };
layout(std430, binding = 18) writeonly buffer Packed { DrawCommand u_packed[]; };
layout(std430, binding = 19) readonly buffer Batches { uvec2 u_batches[]; };  // per batch: first command, command count
layout(std430, binding = 21) writeonly buffer Counts { uint u_counts[]; };

uniform uint u_count_offset;  // this phase's first count (in uints)

shared uint s_kept[64];
shared uint s_written;

void main() {
  uvec2 batch = u_batches[gl_WorkGroupID.x];
  uint lane = gl_LocalInvocationIndex;
  if (lane == 0u) s_written = 0u;
  barrier();
  for (uint chunk = 0u; chunk < batch.y; chunk += 64u) {
    uint i = chunk + lane;
    bool kept = i < batch.y && u_in[batch.x + i].instance_count > 0u;
    s_kept[lane] = kept ? 1u : 0u;
    barrier();
    // Inclusive scan: s_kept[lane] becomes the kept commands up to this lane.
    for (uint offset = 1u; offset < 64u; offset <<= 1) {
      uint before = lane >= offset ? s_kept[lane - offset] : 0u;
      barrier();
      s_kept[lane] += before;
      barrier();
    }
    if (kept) u_packed[batch.x + s_written + s_kept[lane] - 1u] = u_in[batch.x + i];
    barrier();
    if (lane == 63u) s_written += s_kept[63];
    barrier();
  }
  if (lane == 0u) u_counts[u_count_offset + gl_WorkGroupID.x] = s_written;
}
