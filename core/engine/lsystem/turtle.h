#pragma once

#include "engine/lsystem/modulestring.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::lsys {

/// Defaults of the turtle; a grammar's header (angle:, step:, width:, width_factor:) overrides
/// them, and module parameters override them per module.
struct TurtleSettings {
    double angleDegrees = 90.0; ///< default for + - & ^ \ / (degrees)
    double step = 1.0;          ///< default F/f length (metres)
    double width = 0.1;         ///< initial width = branch DIAMETER in metres (radius = width/2)
    double widthFactor = 0.7;   ///< ! without parameter multiplies width by this
    double leafSize = 0.1;      ///< J without parameter: leaf card length (metres)
};

/// Interprets a derived word with a 3D turtle (ABOP ch. 1.5): F draw, f move, + - yaw about up,
/// & ^ pitch about left, \ / roll about heading, | turn around, [ ] push/pop, ! width
/// (with parameter: set width; without: multiply by widthFactor), $ roll so left is horizontal,
/// % cut the rest of the branch (skip to the matching ]), J leaf. Parameters override the
/// default angle/step/width. Starts at the origin heading +Y, frame per skeleton.h.
///
/// Sign conventions (ABOP, in our frame heading +Y, left -X, up +Z at the start):
/// `+` turns left (heading towards left, counter-clockwise seen from above the up vector),
/// `-` turns right; `&` pitches down (heading towards -up), `^` pitches up; `\` rolls left
/// (up towards left), `/` rolls right; `|` turns 180° about up.
///
/// Skeleton choices: every F appends one node whose parent is the turtle's current node (the
/// first F of a tree also creates the root node at its start point); consecutive F's give
/// consecutive nodes. Inside `[` the branch order is one higher, so the first F after `[`
/// starts a lateral branch (order+1) at the current node. `f` moves without drawing and
/// detaches the turtle, so the next F starts a new root (a disconnected tree). The node radius
/// is width/2 at the time of the F; the root takes the width at its creation. A leaf (`J`)
/// hangs on the current node (-1 before the first F) with the turtle's current frame.
/// Symbols without a turtle meaning are skipped; an unmatched `]` is ignored (the grammar
/// checks balance). Throws Cancelled when \p progress asks to stop. When the word carries rule
/// origins (DeriveOptions::traceRules), Skeleton::sourceLine gets the line of the rule that
/// wrote each node's F (a root takes the line of the F that created it).
skel::Skeleton interpret(const ModuleString& word, const TurtleSettings& settings,
                         Progress& progress = noProgress());

} // namespace sylva::lsys
