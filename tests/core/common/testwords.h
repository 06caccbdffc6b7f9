#pragma once

#include <cstdlib>
#include <string>

#include "engine/lsystem/modulestring.h"

namespace sylva::testing {

/// Builds a ModuleString from text such as "F(2)[+(30)F]J": one character per module, with an
/// optional comma-separated parameter list. Only for tests and benchmarks (no error handling).
inline lsys::ModuleString makeWord(const std::string& text) {
    lsys::ModuleString word;
    bool anyParams = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        word.symbols.push_back(text[i]);
        std::uint8_t count = 0;
        if (i + 1 < text.size() && text[i + 1] == '(') {
            anyParams = true;
            std::size_t j = i + 2;
            while (true) {
                char* end = nullptr;
                word.params.push_back(std::strtod(text.c_str() + j, &end));
                ++count;
                j = static_cast<std::size_t>(end - text.c_str());
                if (text[j] == ',') {
                    ++j;
                    continue;
                }
                break; // ')'
            }
            i = j;
        }
        word.paramCounts.push_back(count);
    }
    if (!anyParams) word.paramCounts.clear();
    return word;
}

/// Rewrites every \p from in \p axiom with \p to, \p n times (a context-free D0L system with
/// one rule), for test trees that do not depend on the grammar module.
inline std::string rewrite(std::string axiom, char from, const std::string& to, int n) {
    for (int g = 0; g < n; ++g) {
        std::string next;
        next.reserve(axiom.size() * to.size());
        for (char c : axiom) {
            if (c == from)
                next += to;
            else
                next.push_back(c);
        }
        axiom.swap(next);
    }
    return axiom;
}

/// A bushy 3D test tree: F segments with lateral branches in all directions, tapering widths
/// and leaves at the branch ends.
inline std::string testTreeWord(int generations) {
    return rewrite("!(0.4)X", 'X', "F[&(30)!XJ]/(137)F[&(40)!XJ]/(90)!FX", generations);
}

} // namespace sylva::testing
