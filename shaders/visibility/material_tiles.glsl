// The material classification's output (classify.comp, then
// material_lists.comp): per material, the range of the tile lists that holds
// the tiles showing it and the indirect dispatch of its resolve over them;
// per tile, the materials it shows. A tile is a work group of classify.comp
// and of the resolve (8x8 pixels); its slots are numbered row by row, the
// lists name it by column and row. C++ twins:
// MaterialTiles and the sizes of VisibilityTechnique::reserve_tiles.

// GL's DispatchIndirectCommand (x, y, z: a work group per tile of the range,
// folded into rows of at most 65,535), then the range.
struct MaterialTiles {
  uint x, y, z;
  uint tile_count;  // counted by the classification
  uint first_tile;  // into u_tiles, from the scan of the counts
  uint next_tile;   // the scatter's cursor, from first_tile on
};
layout(std430, binding = 27) buffer MaterialDispatch { MaterialTiles u_material_tiles[]; };
// Each tile as its column | row << 16.
layout(std430, binding = 28) buffer MaterialTileLists { uint u_tiles[]; };
const uint kNoTile = 0xffffffffu;  // column and row beyond any image
// Per tile, u_tile_slots + 1 words: how many materials it shows, then those materials.
layout(std430, binding = 30) buffer TileMaterials { uint u_tile_materials[]; };
// The most materials one tile can show: the fewest of the materials the
// buffers hold room for and the tile's samples (64 pixels times the samples).
uniform uint u_tile_slots;

uint tile_materials_at(uint tile) { return tile * (u_tile_slots + 1u); }
