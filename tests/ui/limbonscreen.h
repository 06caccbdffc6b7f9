// A limb of a drawn tree as a tester's mouse finds it: the Branch tool tests of the 3D view and
// of the species preview click, drag and delete there.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <QPoint>

#include "document/document.h"
#include "ui/generation/treebranches.h"
#include "ui/viewport/tools/branchtool.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui::test {

/// A pixel of \p view where a limb of tree \p id (a branch with a dot in its id: order 1 and
/// up) is drawn and picked by \p tool, walking each limb of order 1 from its base, and the
/// branch picked there; empty when none is.
inline std::pair<QPoint, std::string> limbOnScreen(const Viewport& view, const BranchTool& tool,
                                                   const DrawnTree& drawn, doc::TreeId id,
                                                   const std::vector<skel::BranchEdit>& edits) {
    for (const skel::Branch& b : editedBranchesOf(drawn, edits)) {
        if (b.order != 1) continue;
        for (float f : {0.3f, 0.45f, 0.6f, 0.2f}) {
            const glm::vec3 local = b.base + f * (b.tip - b.base);
            const auto p = view.project(glm::vec3(drawn.transform * glm::vec4(local, 1.0f)));
            if (!p) continue;
            const auto hit = tool.branchAt(p->toPoint());
            if (hit && hit->tree == id && hit->branch.find('.') != std::string::npos)
                return {p->toPoint(), hit->branch};
        }
    }
    return {};
}

} // namespace sylva::ui::test
