#pragma once
// Parameters shared by the self-organizing tests.

#include "engine/growth/selforganizing.h"

namespace sylva::growth::test {

/// A vigorous shadow-propagation tree (the benchmark's tree, tests/bench/growth): large enough
/// after ~10 cycles for every parallel loop of a cycle and the batched difference-array shadow
/// update to split their work, with heavy shedding.
inline SelfOrganizingParams vigorousParams(int cycles) {
    SelfOrganizingParams p;
    p.environment = SoEnvironment::ShadowPropagation;
    p.cycles = cycles;
    p.alpha = 4.0;
    p.shadowA = 0.2;
    p.internodeLength = 0.25;
    p.branchAngle = 85;
    p.optimalWeight = 0.05;
    p.tropismWeight = 0.5;
    return p;
}

} // namespace sylva::growth::test
