// The materials an 8x8 tile of the visibility buffer shows, a slot per sample
// of each pixel (kNone: no geometry there, or named at an earlier slot of the
// same pixel). The classification (classify.comp) and the bindless resolve
// both act once per material of the tile, at the first slot that holds it.

const uint kNone = 0xffffffffu;
shared uint s_slot_material[64 * kSamples];

// Whether `slot` is the first of the tile to hold its material (kNone never is).
bool first_slot_of_its_material(uint slot) {
  uint material = s_slot_material[slot];
  if (material == kNone) return false;
  for (uint k = 0u; k < slot; ++k) {
    if (s_slot_material[k] == material) return false;
  }
  return true;
}
