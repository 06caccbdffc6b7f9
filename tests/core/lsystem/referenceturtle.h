// The straightforward turtle (the first version of engine/lsystem/turtle.cpp, kept verbatim):
// the oracle of the optimized interpreter in the tests (same floats, node by node) and its
// same-run baseline in the benchmark. Only for tests and benchmarks.
#pragma once

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "engine/lsystem/turtle.h"

namespace sylva::lsys::reference {

namespace reference_detail {

// The turtle state is kept in double precision so long derivations do not drift; the skeleton
// stores floats.
struct State {
    glm::dvec3 position{0.0};
    glm::dquat frame{1.0, 0.0, 0.0, 0.0};
    double width = 0.1;
    std::int32_t node = -1;
    std::uint16_t order = 0;
};

// Rotation about a local axis (x, y, z unit) by the angle whose half-angle cosine/sine are c, s.
inline glm::dquat localRotation(int axis, double c, double s) {
    glm::dquat r(c, 0.0, 0.0, 0.0);
    r[axis] = s; // glm's quaternion subscript: 0=x, 1=y, 2=z, 3=w (GLM_FORCE_XYZW_ONLY)
    return r;
}

struct Rotations {
    double c = 1.0;
    double s = 0.0;
};

inline Rotations halfAngle(double degrees) {
    const double h = degrees * (std::numbers::pi / 360.0);
    return {std::cos(h), std::sin(h)};
}

// Parametric words repeat a few angles (e.g. &(30) /(137.5)); caching their half-angle
// cosine/sine avoids two trig calls per module.
class AngleCache {
public:
    const Rotations& get(double degrees) {
        for (Entry& e : mEntries)
            if (e.degrees == degrees) return e.r;
        Entry& e = mEntries[mNext];
        mNext = (mNext + 1) % kSize;
        e.degrees = degrees;
        e.r = halfAngle(degrees);
        return e.r;
    }

private:
    static constexpr std::size_t kSize = 8;
    struct Entry {
        double degrees = std::numeric_limits<double>::quiet_NaN();
        Rotations r;
    };
    Entry mEntries[kSize];
    std::size_t mNext = 0;
};

inline void rotate(State& st, int axis, double sign, const Rotations& r) {
    st.frame = glm::normalize(st.frame * localRotation(axis, r.c, sign * r.s));
}

// $: rotate about the heading so that left is horizontal (ABOP: L = V x H / |V x H|, U = H x L)
// with V = +Y, our world up. Leaves the frame alone when the heading is (nearly) vertical.
inline void levelLeft(State& st) {
    const glm::dvec3 h = st.frame * glm::dvec3(0, 1, 0);
    glm::dvec3 l = glm::cross(glm::dvec3(0, 1, 0), h);
    const double len = glm::length(l);
    if (len < 1e-9) return;
    l /= len;
    const glm::dvec3 u = glm::cross(h, l);
    // Columns: images of the local x, y, z axes (local x is -left).
    st.frame = glm::normalize(glm::quat_cast(glm::dmat3(-l, h, u)));
}

} // namespace reference_detail

using namespace reference_detail;

inline skel::Skeleton interpretReference(const ModuleString& word, const TurtleSettings& settings,
                                         Progress& progress = noProgress()) {
    skel::Skeleton skeleton;
    const std::string& symbols = word.symbols;
    const std::size_t n = symbols.size();
    const bool hasParams = word.hasParams();

    // Reserving exactly avoids reallocation, which dominates the cost on large words.
    std::size_t drawCount = 0;
    for (char c : symbols)
        drawCount += c == 'F' ? 1 : 0;
    skeleton.reserve(drawCount + 1);

    const Rotations defaultTurn = halfAngle(settings.angleDegrees);
    AngleCache angles;
    State st;
    st.width = settings.width;
    std::vector<State> stack;
    stack.reserve(64);

    std::size_t paramIndex = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const char c = symbols[i];
        std::size_t count = 0;
        const double* p = nullptr;
        if (hasParams) {
            count = word.paramCounts[i];
            p = word.params.data() + paramIndex;
            paramIndex += count;
        }
        if ((i & 0xFFFFF) == 0xFFFFF) {
            progress.checkCancelled();
            progress.report(static_cast<double>(i) / static_cast<double>(n), "interpret");
        }
        switch (c) {
        case 'F': {
            const double len = count > 0 ? p[0] : settings.step;
            if (st.node < 0)
                st.node =
                    skeleton.addNode(glm::vec3(st.position), -1, static_cast<float>(st.width * 0.5),
                                     st.order, glm::quat(st.frame));
            st.position += st.frame * glm::dvec3(0.0, len, 0.0);
            st.node =
                skeleton.addNode(glm::vec3(st.position), st.node,
                                 static_cast<float>(st.width * 0.5), st.order, glm::quat(st.frame));
            break;
        }
        case 'f': {
            const double len = count > 0 ? p[0] : settings.step;
            st.position += st.frame * glm::dvec3(0.0, len, 0.0);
            st.node = -1;
            break;
        }
        case '+':
            rotate(st, 2, 1.0, count > 0 ? angles.get(p[0]) : defaultTurn);
            break;
        case '-':
            rotate(st, 2, -1.0, count > 0 ? angles.get(p[0]) : defaultTurn);
            break;
        case '&': // about local left (-x): heading goes towards -up
            rotate(st, 0, -1.0, count > 0 ? angles.get(p[0]) : defaultTurn);
            break;
        case '^':
            rotate(st, 0, 1.0, count > 0 ? angles.get(p[0]) : defaultTurn);
            break;
        case '\\': // about heading (+y) by -angle: up goes towards left
            rotate(st, 1, -1.0, count > 0 ? angles.get(p[0]) : defaultTurn);
            break;
        case '/':
            rotate(st, 1, 1.0, count > 0 ? angles.get(p[0]) : defaultTurn);
            break;
        case '|':
            st.frame = st.frame * glm::dquat(0.0, 0.0, 0.0, 1.0);
            break;
        case '$':
            levelLeft(st);
            break;
        case '!':
            st.width = count > 0 ? p[0] : st.width * settings.widthFactor;
            break;
        case '[':
            stack.push_back(st);
            ++st.order;
            break;
        case ']':
            if (!stack.empty()) {
                st = stack.back();
                stack.pop_back();
            }
            break;
        case '%': {
            // Skip to the matching ']' (or the end) so that it pops normally next.
            int depth = 0;
            std::size_t j = i + 1;
            for (; j < n; ++j) {
                if (symbols[j] == '[') {
                    ++depth;
                } else if (symbols[j] == ']') {
                    if (depth == 0) break;
                    --depth;
                }
                if (hasParams) paramIndex += word.paramCounts[j];
            }
            i = j - 1;
            break;
        }
        case 'J': {
            skel::Leaf leaf;
            leaf.position = glm::vec3(st.position);
            leaf.orientation = glm::quat(st.frame);
            leaf.size = static_cast<float>(count > 0 ? p[0] : settings.leafSize);
            leaf.node = st.node;
            skeleton.leaves.push_back(leaf);
            break;
        }
        default:
            break;
        }
    }
    skeleton.finalize();
    progress.report(1.0, "interpret");
    return skeleton;
}

} // namespace sylva::lsys::reference
