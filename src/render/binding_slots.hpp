// Every binding point that the frame's shaders share, in one table: storage
// and uniform blocks (GLSL `layout(binding = N)` on a block), the texture
// units that stay bound across passes, and the image units of the compute
// passes. A pass's own sampler inputs (units 0-7 of a full-screen pass) are
// its own and stay in its file. kBlockSlots names each GLSL block with its
// slot; BindingSlots.EveryShaderBlockIsAtItsSlot holds every shader to it.
#pragma once

#include <string_view>

#include "gfx/readback_ring.hpp"

namespace atrium::render {

// Storage blocks (std430) and uniform blocks (std140).
inline constexpr unsigned kFrameUniformBinding = 0;    // FrameBlock: camera, viewport, light count
inline constexpr unsigned kClusterUniformBinding = 1;  // ClusterBlock: the cluster grid's shape and slicing
inline constexpr unsigned kLightStorageBinding = 0;    // LightBlock: the frame's lights
inline constexpr unsigned kInstanceStorageBinding = 1;  // Instances
inline constexpr unsigned kLightRangesBinding = 2;      // LightRanges: each bin's range of its list
inline constexpr unsigned kLightIndicesBinding = 3;     // LightIndices
inline constexpr unsigned kBinBoundsBinding = 4;        // Bounds (clusters), TileBoundsBlock (tiles)
inline constexpr unsigned kLightTotalBinding = 5;       // LightTotal
inline constexpr unsigned kPerClusterBinding = 6;       // PixelBounds or Active: what the pixels mark per cluster
inline constexpr unsigned kBinCountsBinding = 7;        // BinCounts
inline constexpr unsigned kMaterialStorageBinding = 8;  // Materials
inline constexpr unsigned kShadowViewBinding = 9;       // ShadowViews
inline constexpr unsigned kDepthTilesBinding = 10;      // Pyramid, TileDepths: occlusion culling's depth
inline constexpr unsigned kBlockSumsBinding = 11;       // BlockSums: the debug counters' sums
inline constexpr unsigned kBigLightsBinding = 12, kOverflowLightsBinding = 13, kLightFitsBinding = 14, kLongBinsBinding = 15;
inline constexpr unsigned kScanBlocksBinding = 22;      // ScanBlocks: the light lists' scan, per block of bins
inline constexpr unsigned kCommandTemplateBinding = 16, kCullOutBinding = 17, kCullShownBinding = 18, kCullRecordsBinding = 19,
                          kLastShownBinding = 20, kCullCountersBinding = 21;  // GPU occlusion culling
inline constexpr unsigned kVisibilityUnitsBinding = 24;  // Units: the visibility buffer's identifiers (render/frame/draw_list.hpp)
inline constexpr unsigned kVertexPoolBinding = 25, kIndexPoolBinding = 26;  // VertexPool, IndexPool: GpuAssets' pools
inline constexpr unsigned kMaterialDispatchBinding = 27, kMaterialTilesBinding = 28,  // the visibility buffer's material tiles:
                          kTileMaterialsBinding = 30;  // MaterialDispatch, MaterialTileLists, TileMaterials
inline constexpr unsigned kMaterialTexturesBinding = 29;  // MaterialTextures: bindless handles (render/techniques/visibility)
inline constexpr unsigned kReadbackSourceBinding = gfx::kReadbackSourceBinding;  // ReadbackSource, ReadbackSlot: a
inline constexpr unsigned kReadbackSlotBinding = gfx::kReadbackSlotBinding;      // readback ring's copy (gfx/readback_ring.hpp)

// Texture units that stay bound while passes run: clear of a full-screen
// pass's inputs and the materials' textures (0-7), within the 16 a WebGL2
// fragment shader may sample.
inline constexpr unsigned kLightRangeTextureUnit = 8, kLightIndexTextureUnit = 9;  // the compute-free tier's light lists
inline constexpr unsigned kLightTextureUnit = 10, kInstanceTextureUnit = 11, kMaterialTextureUnit = 12;  // ... its records
inline constexpr unsigned kShadowViewTextureUnit = 13;
inline constexpr unsigned kDepthTextureUnit = 14;  // occlusion culling's depth read
inline constexpr unsigned kShadowAtlasUnit = 15;
inline constexpr unsigned kVisibilityUnit = 5;  // the visibility buffer's identifiers, beside the materials' 0-4

// Image units of compute passes (shaders/common/lighting_targets.glsl); the
// heatmap's light counts take unit 0, the fragment counts unit 1.
inline constexpr unsigned kLitColorImageUnit = 2;
inline constexpr unsigned kDiffuseLightImageUnit = 3;
inline constexpr unsigned kSpecularLightImageUnit = 4;
inline constexpr unsigned kDisplayImageUnit = 2;  // the tone map's output (shaders/post/tonemap.comp)
inline constexpr unsigned kPostImageUnit = 5;     // a post-process pass's output (shaders/post/*/*.comp)

// Each GLSL block the frame's shaders declare, with its slot.
struct BlockSlot {
  std::string_view block;
  unsigned binding;
};
inline constexpr BlockSlot kBlockSlots[] = {
    {"FrameBlock", kFrameUniformBinding},       {"ClusterBlock", kClusterUniformBinding},
    {"LightBlock", kLightStorageBinding},       {"Instances", kInstanceStorageBinding},
    {"LightRanges", kLightRangesBinding},       {"LightIndices", kLightIndicesBinding},
    {"Bounds", kBinBoundsBinding},              {"TileBoundsBlock", kBinBoundsBinding},
    {"LightTotal", kLightTotalBinding},         {"PixelBounds", kPerClusterBinding},
    {"Active", kPerClusterBinding},             {"BinCounts", kBinCountsBinding},
    {"Materials", kMaterialStorageBinding},     {"ShadowViews", kShadowViewBinding},
    {"Pyramid", kDepthTilesBinding},            {"TileDepths", kDepthTilesBinding},
    {"BlockSums", kBlockSumsBinding},           {"BigLights", kBigLightsBinding},
    {"OverflowLights", kOverflowLightsBinding}, {"LightFits", kLightFitsBinding},
    {"LongBins", kLongBinsBinding},             {"Template", kCommandTemplateBinding},
    {"In", kCullOutBinding},                    {"Out", kCullOutBinding},
    {"Packed", kCullShownBinding},              {"Shown", kCullShownBinding},
    {"Batches", kCullRecordsBinding},           {"Records", kCullRecordsBinding},
    {"LastShown", kLastShownBinding},           {"Counters", kCullCountersBinding},
    {"Counts", kCullCountersBinding},           {"ReadbackSource", kReadbackSourceBinding},
    {"ReadbackSlot", kReadbackSlotBinding},     {"Units", kVisibilityUnitsBinding},
    {"VertexPool", kVertexPoolBinding},         {"IndexPool", kIndexPoolBinding},
    {"MaterialDispatch", kMaterialDispatchBinding}, {"MaterialTileLists", kMaterialTilesBinding},
    {"MaterialTextures", kMaterialTexturesBinding}, {"ScanBlocks", kScanBlocksBinding},
    {"TileMaterials", kTileMaterialsBinding},
};

}  // namespace atrium::render
