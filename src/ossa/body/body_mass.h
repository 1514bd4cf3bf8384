#pragma once
// The mass of a body (issue 30: the body's volume × 1000 kg/m³ matches the genome's weight at
// the creature's size). Measured on the mesh in its rest (bind) pose:
//
//   tube parts (axial body, legs, arms, horns, trunk, shell): elliptic cross-sections. At each
//     section the outline's height h (the distance between its top and bottom vertices) and a
//     lateral width depth · h (BodyPart::depth: 0.8 for the trunk, 0.55 for a fish's
//     flattened body, 0.75 for limbs, 1 for horns and trunks) give an area π/4 · depth · h²;
//     the volume is the trapezoid sum of those areas along the distance between the sections'
//     midpoints. Round end caps are left out (they are a few percent at most).
//   limbs count from where they leave the trunk: a pair of sections adds its share only for
//     the sections whose midpoint lies outside the axial body's outline (a thigh inside the
//     trunk's silhouette is counted once, as trunk).
//   flat parts (ears, wings, fins, frill, crest, mane, sail, plates, tail fins): their outline's
//     area × thickness, thickness = depth × the outline's longest side (its bounding box).
//   the eye: nothing.
//   density 1000 kg/m³.
//   A body too heavy for its weight even at the least girth (BodyOptions::min_girth), or too
//   light at the most, has every depth scaled by BodyMesh::depth_scale: slimmer or wider
//   across, its side view kept plausible.
//
// `body_mass()` fills BodyPart::mass_kg, BodyMesh::mass_kg and area_m2; the builder calls it,
// and a test recomputes it from the vertices alone.

#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "ossa/body/body_mesh.h"

namespace ossa {

inline constexpr float kBodyDensity = 1000.0f;  // kg/m³

// Volume (m³) of a tube given its sections' top and bottom points, in order, and the lateral
// depth ratio; `counts` (empty: all 1) is each section's share (0 or 1), and a pair of
// sections adds the mean of their shares.
double tube_volume(std::span<const glm::vec2> tops, std::span<const glm::vec2> bottoms, float depth,
                   std::span<const float> counts = {});
// Area (m²) of a closed polygon (absolute; any orientation).
double polygon_area(std::span<const glm::vec2> polygon);
// Whether p lies inside the closed polygon (even-odd rule).
bool inside_polygon(std::span<const glm::vec2> polygon, glm::vec2 p);

// Measures every part and the whole body (see above).
void body_mass(BodyMesh& mesh);

}  // namespace ossa
