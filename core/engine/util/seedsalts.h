#pragma once

#include <cstdint>

/// The salts each stage mixes into a seed (`mixSeed(seed, salt)`) so that its random stream is
/// its own: one name per salt, in one place. A stage and anyone who repeats its stream (the
/// forest meshing a tree as its tube_mesh node would) use the same constant. Changing a value
/// changes every output that draws from it: they are part of the byte-identical guarantee.
namespace sylva::salt {

/// Leaf thinning of a tree's mesh (the tube_mesh node, the forest's meshing of each tree).
inline constexpr std::uint64_t kTreeMesh = 0x7EAF;
/// Leaf placement of the `leaves` node.
inline constexpr std::uint64_t kLeafPlacement = 0x1EAF;
/// Space colonization's attraction points ("colonize").
inline constexpr std::uint64_t kSpaceColonization = 0x636f6c6f6e697a65ull;
/// Points sampled inside a crown envelope ("envelope").
inline constexpr std::uint64_t kEnvelope = 0x656e76656c6f7065ull;
/// Space colonization's lit attraction points: the jitter of the sunlit clusters ("light").
inline constexpr std::uint64_t kLitAttractors = 0x6c69676874ull;
/// A self-organizing tree's own stream (bud fates over the whole growth).
inline constexpr std::uint64_t kSelfOrganizingTree = 0x5e1f;
/// A self-organizing tree's space-colonization markers in its crown.
inline constexpr std::uint64_t kSelfOrganizingMarkers = 0x3a7c;
/// A self-organizing growth cycle: the cycle number is added, then each bud mixes its own index.
inline constexpr std::uint64_t kSelfOrganizingCycle = 0x5400;
/// A forest's sample tree of each species (crown measurement): the species index is added.
inline constexpr std::uint64_t kCrownSample = 0xC0000;
/// The shuffle of species slots within one placement domain (the domain index is mixed in).
inline constexpr std::uint64_t kDomainSlots = 0xD0A1;
/// A placed tree's rotation, scale and growth stage, from its own seed.
inline constexpr std::uint64_t kPlacedTree = 0x0A11;
/// Wind: the phase of each sway element (mixed with the element's first node) and, plus one, of
/// each node's leaf flutter.
inline constexpr std::uint64_t kWindPhase = 0x771D0;
/// The editor's viewport: where in the wind's loop a tree plays, mixed with the tree's id.
inline constexpr std::uint64_t kViewWindPhase = 0x771D7;
/// A species' variants (forest instancing): mixed with the project seed, then the species name's
/// hash, then the variant index.
inline constexpr std::uint64_t kVariant = 0x5A1A7;
/// Which of its species' variants an instanced tree shows, from the tree's own seed.
inline constexpr std::uint64_t kVariantPick = 0x5A1B;
/// Which leaves a deciduous tree keeps in spring and autumn, from its mesh seed ("season").
inline constexpr std::uint64_t kSeason = 0x5EA5;
/// The editor's Brush tool: a stroke's trees (added to the tree count of the stroke).
inline constexpr std::uint64_t kBrushStroke = 7919;
/// The editor's Place tool: a placed tree's rotation and seed (added to the tree count).
inline constexpr std::uint64_t kPlaceTool = 104729;
/// Leaf cluster cards: which atlas tile a cluster shows and whether it is mirrored.
inline constexpr std::uint64_t kLeafClusters = 0x5b7a11ull;
/// Leaf cards' colour variation (mesh/leaftint.h): each card's own random and the crown's noise.
inline constexpr std::uint64_t kLeafTint = 0x7147ull;

} // namespace sylva::salt
