// Lit rooms of a triangle twin with their windows' looks (host). The renderer gives each lit room
// its own colour temperature and brightness from hashes (lights/window_light.h); stored triangles
// share materials, so each window's look is rounded to the nearest of a small palette of emitting
// materials: kLitRoomColours colours from 2700 K to 4000 K times kLitRoomLevels mean intensities.
// What the palette leaves out: the curtain's shape (its dimming is in the mean) and the noise.
#pragma once

#include "lights/window_light.h"
#include "scene/material.h"

#include <cstdint>
#include <vector>

namespace urbis {

inline constexpr uint32_t kLitRoomColours = 5, kLitRoomLevels = 8;
inline constexpr uint32_t kLitRoomPaletteSize = kLitRoomColours * kLitRoomLevels;
/// The palette's mean intensities (windowMeanIntensity), evenly from the lowest to the highest a
/// look has: an intensity of 0.5 behind a curtain over four fifths of the window, to 1.5.
inline constexpr float kLitRoomLevelLow = 0.25f, kLitRoomLevelHigh = 1.5f;

/// The palette's entry of a look: the nearest colour and the nearest level.
uint32_t litRoomPaletteEntry(const WindowLook& look);

/// Coolness (WindowLook::coolness) and mean intensity of a palette entry.
float litRoomEntryCoolness(uint32_t entry);
float litRoomEntryIntensity(uint32_t entry);

/// The palette's materials in entry order: `litRoom` (FacadeMaterial::RoomLit's) emitting its
/// luminance times each entry's colour and intensity, as windowRadiance does.
std::vector<Material> litRoomPaletteMaterials(const Material& litRoom);

} // namespace urbis
