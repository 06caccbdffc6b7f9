#include "engine/lsystem/turtle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "engine/util/error.h"
#include "engine/util/hugepages.h"

namespace sylva::lsys {

namespace {

// Half-angle cosine and sine of a rotation.
struct Turn {
    double c = 1.0;
    double s = 0.0;
};

inline Turn halfAngle(double degrees) {
    const double h = degrees * (std::numbers::pi / 360.0);
    return {std::cos(h), std::sin(h)};
}

// Parametric words repeat a few angles (e.g. &(30) /(137.5)); caching their half-angle
// cosine/sine avoids two trig calls per module.
class AngleCache {
public:
    const Turn& get(double degrees) {
        for (Entry& e : mEntries)
            if (e.degrees == degrees) return e.turn;
        Entry& e = mEntries[mNext];
        mNext = (mNext + 1) % kSize;
        e.degrees = degrees;
        e.turn = halfAngle(degrees);
        return e.turn;
    }

private:
    static constexpr std::size_t kSize = 8;
    struct Entry {
        double degrees = std::numeric_limits<double>::quiet_NaN();
        Turn turn;
    };
    Entry mEntries[kSize];
    std::size_t mNext = 0;
};

// frame * (c + s·e_axis), normalized: glm's quaternion product with the zero terms of the
// local rotation left out (same operations in the same order otherwise, so the result equals
// the general product up to the sign of an exact zero).
template <int Axis> inline void rotate(glm::dquat& q, double c, double s) {
    const glm::dquat p = q;
    if constexpr (Axis == 0) {
        q.w = p.w * c - p.x * s;
        q.x = p.w * s + p.x * c;
        q.y = p.y * c + p.z * s;
        q.z = p.z * c - p.y * s;
    } else if constexpr (Axis == 1) {
        q.w = p.w * c - p.y * s;
        q.x = p.x * c - p.z * s;
        q.y = p.w * s + p.y * c;
        q.z = p.z * c + p.x * s;
    } else {
        q.w = p.w * c - p.z * s;
        q.x = p.x * c + p.y * s;
        q.y = p.y * c - p.x * s;
        q.z = p.w * s + p.z * c;
    }
    q = glm::normalize(q);
}

// q·(0, len, 0): glm's rotation of a vector with the zero terms left out.
inline glm::dvec3 forward(const glm::dquat& q, double len) {
    const double uvx = -(len * q.z);
    const double uvz = q.x * len;
    const double uuvx = q.y * uvz;
    const double uuvy = q.z * uvx - uvz * q.x;
    const double uuvz = -(uvx * q.y);
    return {(uvx * q.w + uuvx) * 2.0, len + uuvy * 2.0, (uvz * q.w + uuvz) * 2.0};
}

// $: rotate about the heading so that left is horizontal (ABOP: L = V x H / |V x H|, U = H x L)
// with V = +Y, our world up. Leaves the frame alone when the heading is (nearly) vertical.
inline glm::dquat levelLeft(const glm::dquat& frame) {
    const glm::dvec3 h = frame * glm::dvec3(0, 1, 0);
    glm::dvec3 l = glm::cross(glm::dvec3(0, 1, 0), h);
    const double len = glm::length(l);
    if (len < 1e-9) return frame;
    l /= len;
    const glm::dvec3 u = glm::cross(h, l);
    // Columns: images of the local x, y, z axes (local x is -left).
    return glm::normalize(glm::quat_cast(glm::dmat3(-l, h, u)));
}

// Nodes the word creates: one per F plus one root per tree. Counted exactly here only for the
// common case of a word with a single tree (no f); otherwise the arrays grow as needed.
std::size_t estimateNodes(const std::string& symbols) {
    std::size_t draws = 0;
    for (char c : symbols)
        draws += c == 'F' ? 1 : 0;
    return draws + 1;
}

// Skeleton::addNode plus finalize()'s flags, inlined: the arrays are reserved, and a call whose
// arguments are passed in memory would keep the turtle state out of registers.
[[gnu::always_inline]] inline std::int32_t appendNode(skel::Skeleton& s, glm::vec3 p,
                                                      std::int32_t parent, float r,
                                                      std::uint16_t order, glm::quat q) {
    const auto index = static_cast<std::int32_t>(s.position.size());
    s.position.push_back(p);
    s.parent.push_back(parent);
    s.radius.push_back(r);
    s.order.push_back(order);
    s.orientation.push_back(q);
    static_assert(skel::kFork == skel::kTip << 1);
    // The tip/fork flags Skeleton::finalize() would compute, kept up to date here instead
    // (saves finalize's extra pass and child-count array): a new node is a tip; its parent's
    // first child clears the parent's tip bit, a later one marks it a fork.
    s.flags.push_back(skel::kTip);
    if (parent >= 0) {
        std::uint8_t& f = s.flags[static_cast<std::size_t>(parent)];
        f = static_cast<std::uint8_t>((f & ~skel::kTip) | ((~f & skel::kTip) << 1));
    }
    return index;
}

// A saved turtle state ([ pushes, ] pops). The turtle works in double precision so long
// derivations do not drift; the skeleton stores floats.
struct Saved {
    glm::dvec3 position;
    glm::dquat frame;
    double width;
    std::int32_t node;
    std::uint16_t order;
};

// GCC's SLP vectorizer turns the field-by-field save at '[' into 16-byte loads of state that
// was just written as 8-byte scalars (spilled), which stalls on store forwarding: ~10 % of the
// interpreter's time on ABOP words. Scalar copies forward cleanly.
#if defined(__GNUC__) && !defined(__clang__)
#define SYLVA_TURTLE_NO_SLP __attribute__((optimize("no-tree-slp-vectorize")))
#else
#define SYLVA_TURTLE_NO_SLP
#endif

template <bool HasParams, bool Traced>
SYLVA_TURTLE_NO_SLP void run(const ModuleString& word, const TurtleSettings& settings,
                             Progress& progress, skel::Skeleton& skeleton) {
    const char* sym = word.symbols.data();
    const std::size_t n = word.symbols.size();
    const std::uint8_t* counts = HasParams ? word.paramCounts.data() : nullptr;
    const double* params = HasParams ? word.params.data() : nullptr;

    const Turn def = halfAngle(settings.angleDegrees);
    const double step = settings.step;
    AngleCache angles;

    // The state lives in locals (not a struct whose address escapes into push_back), so the
    // compiler keeps it in registers; saving and restoring copy field by field.
    glm::dvec3 position(0.0);
    glm::dquat frame(1.0, 0.0, 0.0, 0.0);
    double width = settings.width;
    std::int32_t node = -1;
    std::uint16_t order = 0;
    std::vector<Saved> stack(64);
    std::size_t depth = 0;

    std::size_t paramIndex = 0;
    std::size_t nextCheck = std::min<std::size_t>(n, 1u << 20);
    std::size_t i = 0;
    while (true) {
        if (i == nextCheck) {
            if (i == n) break;
            progress.checkCancelled();
            progress.report(static_cast<double>(i) / static_cast<double>(n), "interpret");
            nextCheck = std::min<std::size_t>(n, i + (1u << 20));
        }
        const char c = sym[i];
        std::size_t count = 0;
        const double* p = nullptr;
        if constexpr (HasParams) {
            count = counts[i];
            p = params + paramIndex;
            paramIndex += count;
        }
        // The default angle's precomputed half-angle pair, or a parameter's (cached).
        auto turn = [&]() -> Turn { return HasParams && count > 0 ? angles.get(p[0]) : def; };
        switch (c) {
        case 'F': {
            const double len = HasParams && count > 0 ? p[0] : step;
            const glm::quat q(frame);
            const auto r = static_cast<float>(width * 0.5);
            if (node < 0) node = appendNode(skeleton, glm::vec3(position), -1, r, order, q);
            position += forward(frame, len);
            node = appendNode(skeleton, glm::vec3(position), node, r, order, q);
            if constexpr (Traced) skeleton.sourceLine.resize(skeleton.size(), word.origins[i]);
            break;
        }
        case 'f': {
            const double len = HasParams && count > 0 ? p[0] : step;
            position += forward(frame, len);
            node = -1;
            break;
        }
        case '+': {
            const Turn t = turn();
            rotate<2>(frame, t.c, t.s);
            break;
        }
        case '-': {
            const Turn t = turn();
            rotate<2>(frame, t.c, -t.s);
            break;
        }
        case '&': { // about local left (-x): heading goes towards -up
            const Turn t = turn();
            rotate<0>(frame, t.c, -t.s);
            break;
        }
        case '^': {
            const Turn t = turn();
            rotate<0>(frame, t.c, t.s);
            break;
        }
        case '\\': { // about heading (+y) by -angle: up goes towards left
            const Turn t = turn();
            rotate<1>(frame, t.c, -t.s);
            break;
        }
        case '/': {
            const Turn t = turn();
            rotate<1>(frame, t.c, t.s);
            break;
        }
        case '|':
            frame = frame * glm::dquat(0.0, 0.0, 0.0, 1.0);
            break;
        case '$':
            frame = levelLeft(frame);
            break;
        case '!':
            width = HasParams && count > 0 ? p[0] : width * settings.widthFactor;
            break;
        case '[': {
            if (depth == stack.size()) stack.resize(stack.size() * 2);
            Saved& e = stack[depth++];
            e.position = position;
            e.frame = frame;
            e.width = width;
            e.node = node;
            e.order = order;
            ++order;
            break;
        }
        case ']':
            if (depth > 0) {
                const Saved& e = stack[--depth];
                position = e.position;
                frame = e.frame;
                width = e.width;
                node = e.node;
                order = e.order;
            }
            break;
        case '%': {
            // Skip to the matching ']' (or the end) so that it pops normally next.
            int level = 0;
            std::size_t j = i + 1;
            for (; j < n; ++j) {
                if (sym[j] == '[') {
                    ++level;
                } else if (sym[j] == ']') {
                    if (level == 0) break;
                    --level;
                }
                if constexpr (HasParams) paramIndex += counts[j];
            }
            // The skipped modules may have crossed a progress check.
            if (j > nextCheck) nextCheck = j;
            i = j;
            continue;
        }
        case 'J': {
            skel::Leaf leaf;
            leaf.position = glm::vec3(position);
            leaf.orientation = glm::quat(frame);
            leaf.size = static_cast<float>(HasParams && count > 0 ? p[0] : settings.leafSize);
            leaf.node = node;
            skeleton.leaves.push_back(leaf);
            break;
        }
        default:
            break;
        }
        ++i;
    }
}

} // namespace

skel::Skeleton interpret(const ModuleString& word, const TurtleSettings& settings,
                         Progress& progress) {
    skel::Skeleton skeleton;
    skeleton.reserve(estimateNodes(word.symbols));
    adviseHugePages(skeleton.position);
    adviseHugePages(skeleton.parent);
    adviseHugePages(skeleton.radius);
    adviseHugePages(skeleton.order);
    adviseHugePages(skeleton.flags);
    adviseHugePages(skeleton.orientation);
    const bool traced = !word.origins.empty();
    if (traced && word.origins.size() != word.size())
        throw InvalidInput("the word's rule origins do not match its modules");
    if (word.hasParams())
        traced ? run<true, true>(word, settings, progress, skeleton)
               : run<true, false>(word, settings, progress, skeleton);
    else
        traced ? run<false, true>(word, settings, progress, skeleton)
               : run<false, false>(word, settings, progress, skeleton);
    progress.report(1.0, "interpret");
    return skeleton;
}

} // namespace sylva::lsys
