// Clustered forward+'s depth pre-pass with MSAA (SHADING_DEPTH) also writes,
// to a colour target, the depth at the pixel centre, where the shading pass
// will light the fragment; the depth buffer holds each sample's own depth,
// which on a silhouette differs (clustered/mark_active.comp marks clusters from
// this target instead). The visibility buffer's geometry pass writes it beside
// its identifiers (SHADING_DEPTH_LOCATION 1). Without the define it writes nothing.
#ifdef SHADING_DEPTH
#ifndef SHADING_DEPTH_LOCATION
#define SHADING_DEPTH_LOCATION 0
#endif
layout(location = SHADING_DEPTH_LOCATION) out float out_shading_depth;
void write_shading_depth() { out_shading_depth = gl_FragCoord.z; }
#else
void write_shading_depth() {}
#endif
