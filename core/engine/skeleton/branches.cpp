#include "engine/skeleton/branches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <unordered_map>

#include <glm/gtx/quaternion.hpp>

#include "engine/util/error.h"

namespace sylva::skel {

namespace {

using Index = std::int32_t;

std::size_t at(Index i) {
    return static_cast<std::size_t>(i);
}

/// The child an axis goes on in at each node, -1 at a tip.
std::vector<Index> continuations(const Skeleton& s, const std::vector<std::vector<Index>>& kids) {
    std::vector<Index> cont(s.size(), -1);
    for (std::size_t i = 0; i < s.size(); ++i) {
        Index best = -1;
        bool bestSame = false;
        for (Index c : kids[i]) {
            const bool same = s.order[at(c)] == s.order[i];
            if (best < 0 || (same && !bestSame) ||
                (same == bestSame && s.radius[at(c)] > s.radius[at(best)])) {
                best = c;
                bestSame = same;
            }
        }
        cont[i] = best;
    }
    return cont;
}

/// Angle in [0, 2·pi) of \p dir about the axis at node \p k, from the node's turtle left.
float angleAbout(const Skeleton& s, Index k, Index next, const glm::vec3& dir) {
    glm::vec3 axis(0, 1, 0);
    if (s.parent[at(k)] >= 0)
        axis = s.position[at(k)] - s.position[at(s.parent[at(k)])];
    else if (next >= 0)
        axis = s.position[at(next)] - s.position[at(k)];
    if (glm::length(axis) < 1e-9f) axis = glm::vec3(0, 1, 0);
    axis = glm::normalize(axis);
    auto flat = [&axis](const glm::vec3& v) { return v - axis * glm::dot(v, axis); };
    glm::vec3 ref = flat(leftOf(s.orientation[at(k)]));
    if (glm::length(ref) < 1e-4f) ref = flat(glm::vec3(1, 0, 0));
    if (glm::length(ref) < 1e-4f) ref = flat(glm::vec3(0, 0, 1));
    ref = glm::normalize(ref);
    const glm::vec3 side = glm::cross(axis, ref);
    const glm::vec3 d = flat(dir);
    float a = std::atan2(glm::dot(d, side), glm::dot(d, ref));
    if (a < 0.0f) a += 2.0f * std::numbers::pi_v<float>;
    return a;
}

/// Nodes of the subtree that starts at \p first (itself and everything it carries).
std::vector<char> subtree(const Skeleton& s, Index first) {
    std::vector<char> in(s.size(), 0);
    in[at(first)] = 1;
    for (std::size_t i = at(first) + 1; i < s.size(); ++i)
        in[i] = s.parent[i] >= first && in[at(s.parent[i])];
    return in;
}

/// Removes the nodes not kept; indices of the others and of the leaves follow.
void compact(Skeleton& s, const std::vector<char>& remove) {
    const std::size_t n = s.size();
    std::vector<Index> map(n, -1);
    Index next = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!remove[i]) map[i] = next++;
    auto filter = [&](auto& v) {
        if (v.size() != n) return;
        std::size_t w = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (!remove[i]) v[w++] = v[i];
        v.resize(w);
    };
    for (std::size_t i = 0; i < n; ++i)
        if (!remove[i] && s.parent[i] >= 0) s.parent[i] = map[at(s.parent[i])];
    filter(s.position);
    filter(s.parent);
    filter(s.radius);
    filter(s.order);
    filter(s.flags);
    filter(s.orientation);
    filter(s.light);
    filter(s.vigour);
    filter(s.age);
    filter(s.sourceLine);
    std::vector<Leaf> leaves;
    leaves.reserve(s.leaves.size());
    for (Leaf leaf : s.leaves) {
        if (leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < n) {
            if (remove[at(leaf.node)]) continue;
            leaf.node = map[at(leaf.node)];
        }
        leaves.push_back(leaf);
    }
    s.leaves = std::move(leaves);
    s.finalize();
}

std::size_t depthOf(const std::string& id) {
    return static_cast<std::size_t>(std::count(id.begin(), id.end(), '.'));
}

} // namespace

BranchAnchor anchorOf(const Branch& b) {
    BranchAnchor a;
    a.base = b.base;
    const glm::vec3 d = b.tip - b.base;
    a.direction = glm::length(d) > 1e-9f ? glm::normalize(d) : glm::vec3(0.0f, 1.0f, 0.0f);
    a.length = b.length;
    return a;
}

std::vector<Branch> branchesOf(const Skeleton& s) {
    const std::size_t n = s.size();
    std::vector<std::vector<Index>> kids(n);
    for (std::size_t i = 0; i < n; ++i)
        if (s.parent[i] >= 0) kids[at(s.parent[i])].push_back(static_cast<Index>(i));
    const std::vector<Index> cont = continuations(s, kids);

    std::vector<Branch> out;
    auto start = [&](Index first, Index baseNode, std::int32_t parent, std::string id) {
        Branch b;
        b.id = std::move(id);
        b.parentIndex = parent;
        if (parent >= 0) b.parent = out[at(parent)].id;
        b.order = s.order[at(first)];
        b.baseNode = baseNode;
        b.base = s.position[at(baseNode >= 0 ? baseNode : first)];
        b.baseRadius = s.radius[at(first)];
        for (Index k = first; k >= 0; k = cont[at(k)]) {
            b.nodes.push_back(k);
            if (s.parent[at(k)] >= 0)
                b.length += glm::length(s.position[at(k)] - s.position[at(s.parent[at(k)])]);
        }
        b.tip = s.position[at(b.nodes.back())];
        out.push_back(std::move(b));
    };
    int trunks = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (s.parent[i] < 0) start(static_cast<Index>(i), -1, -1, std::to_string(trunks++));

    for (std::size_t b = 0; b < out.size(); ++b) {
        // (node's place along the parent, angle, index) of each branch leaving this one.
        std::vector<std::tuple<std::size_t, float, Index, Index>> leaving;
        const std::vector<Index> chain = out[b].nodes;
        for (std::size_t j = 0; j < chain.size(); ++j) {
            const Index k = chain[j];
            for (Index c : kids[at(k)])
                if (c != cont[at(k)])
                    leaving.emplace_back(
                        j, angleAbout(s, k, cont[at(k)], s.position[at(c)] - s.position[at(k)]), c,
                        k);
        }
        std::sort(leaving.begin(), leaving.end());
        const std::string prefix = out[b].id + ".";
        for (std::size_t r = 0; r < leaving.size(); ++r)
            start(std::get<2>(leaving[r]), std::get<3>(leaving[r]), static_cast<std::int32_t>(b),
                  prefix + std::to_string(r));
    }
    return out;
}

void validate(const BranchEdit& e) {
    if (e.branch.empty()) throw InvalidInput("a branch edit needs a branch id");
    auto scale = [](const char* name, float v) {
        if (!(v >= kBranchScaleMin && v <= kBranchScaleMax))
            throw InvalidInput(std::string("branch edit ") + name + " " + std::to_string(v) +
                               " is out of range [0.05, 20]");
    };
    scale("length", e.length);
    scale("radius", e.radius);
    if (e.bend && !(glm::length(*e.bend) > 1e-6f && std::isfinite(glm::length(*e.bend))))
        throw InvalidInput("branch edit bend must be a non-zero direction");
    if (e.prune && e.branch.find('.') == std::string::npos)
        throw InvalidInput("branch " + e.branch + " is a trunk: it cannot be pruned");
    for (std::size_t i = 0; i < e.locked.size(); ++i)
        if (e.locked[i].parent < -1 || e.locked[i].parent >= static_cast<std::int32_t>(i))
            throw InvalidInput("branch " + e.branch + ": locked node " + std::to_string(i) +
                               " needs a parent before it");
    if (!e.locked.empty() && e.locked.front().parent != -1)
        throw InvalidInput("branch " + e.branch + ": the first locked node leaves the parent");
    for (const LockedLeaf& l : e.lockedLeaves)
        if (l.node < 0 || l.node >= static_cast<std::int32_t>(e.locked.size()))
            throw InvalidInput("branch " + e.branch + ": a locked leaf names no locked node");
}

namespace {

std::string parentId(const std::string& id) {
    const std::size_t dot = id.rfind('.');
    return dot == std::string::npos ? std::string() : id.substr(0, dot);
}

/// Appends \p e's locked geometry to \p s, leaving node \p at (base \p base).
void graft(Skeleton& s, const BranchEdit& e, Index at, const glm::vec3& base) {
    const auto first = static_cast<Index>(s.size());
    for (const LockedNode& n : e.locked) {
        s.addNode(base + n.offset, n.parent < 0 ? at : first + n.parent, n.radius, n.order,
                  n.orientation); // extends the growth records and source lines too
    }
    for (const LockedLeaf& l : e.lockedLeaves) {
        Leaf leaf;
        leaf.position = base + l.offset;
        leaf.orientation = l.orientation;
        leaf.size = l.size;
        leaf.node = first + l.node;
        s.leaves.push_back(leaf);
    }
}

} // namespace

BranchEditReport applyBranchEdits(Skeleton& s, const std::vector<BranchEdit>& edits,
                                  std::vector<std::int32_t>* nodeMap) {
    BranchEditReport report;
    if (nodeMap) {
        nodeMap->resize(s.size());
        for (std::size_t i = 0; i < s.size(); ++i)
            (*nodeMap)[i] = static_cast<Index>(i);
    }
    if (edits.empty()) return report;
    for (const BranchEdit& e : edits)
        validate(e);
    const std::vector<Branch> branches = branchesOf(s);
    std::unordered_map<std::string, std::size_t> byId;
    for (std::size_t i = 0; i < branches.size(); ++i)
        byId.emplace(branches[i].id, i);

    // Where each edit goes: anchored edits to the branch at their anchor (their id's own when it
    // is still there), the others, and anchored ones that find none, by id. Parents first, so a
    // branch's edit claims it before a deeper one could.
    float height = 0.0f;
    if (s.size() > 0) {
        float lo = s.position[0].y, hi = lo;
        for (const glm::vec3& p : s.position) {
            lo = std::min(lo, p.y);
            hi = std::max(hi, p.y);
        }
        height = hi - lo;
    }
    const float cosLimit = std::cos(glm::radians(kAnchorAngle));
    std::vector<char> claimed(branches.size(), 0);
    auto anchorCost = [&](const BranchAnchor& a, const Branch& b) {
        const float reach = kAnchorReach * height + a.length;
        const glm::vec3 d = b.tip - b.base;
        if (glm::length(d) < 1e-9f) return std::numeric_limits<float>::max();
        const float c = glm::dot(glm::normalize(d), a.direction);
        const float dist = glm::length(b.base - a.base);
        if (dist > reach || c < cosLimit) return std::numeric_limits<float>::max();
        return dist / std::max(reach, 1e-6f) + (1.0f - c) / (1.0f - cosLimit);
    };
    // Anchored edits, one depth after another (parents first): the pairs of edit and branch
    // within reach, nearest first, each edit and branch taken once (a greedy matching, so that
    // an edit does not take the branch another edit fits better).
    std::unordered_map<const BranchEdit*, std::ptrdiff_t> target;
    // A locked edit keeps its own id (and, where that is gone, is grafted where it was): its
    // kept geometry is its anchor.
    for (const BranchEdit& e : edits)
        if (e.lock && !e.locked.empty())
            if (const auto found = byId.find(e.branch); found != byId.end()) {
                claimed[found->second] = 1;
                target[&e] = static_cast<std::ptrdiff_t>(found->second);
            }
    std::size_t maxDepth = 0;
    for (const BranchEdit& e : edits)
        maxDepth = std::max(maxDepth, depthOf(e.branch));
    for (std::size_t depth = 0; depth <= maxDepth; ++depth) {
        std::vector<std::tuple<float, const BranchEdit*, std::size_t>> pairs;
        for (const BranchEdit& e : edits) {
            if (!e.anchor || depthOf(e.branch) != depth || (e.lock && !e.locked.empty())) continue;
            for (std::size_t i = 0; i < branches.size(); ++i) {
                if (depthOf(branches[i].id) != depth) continue;
                float c = anchorCost(*e.anchor, branches[i]);
                if (c == std::numeric_limits<float>::max()) continue;
                if (branches[i].id == e.branch) c *= 0.5f; // its own id, where it was: kept
                pairs.emplace_back(c, &e, i);
            }
        }
        std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) {
            return std::get<0>(x) < std::get<0>(y);
        });
        for (const auto& [cost, e, i] : pairs) {
            (void)cost;
            if (claimed[i] || target.count(e)) continue;
            claimed[i] = 1;
            target[e] = static_cast<std::ptrdiff_t>(i);
        }
    }
    auto resolve = [&](const BranchEdit& e) -> std::ptrdiff_t {
        if (auto t = target.find(&e); t != target.end()) return t->second;
        // By id: an edit without an anchor, or one whose anchor found no branch near.
        const auto found = byId.find(e.branch);
        if (found == byId.end() || claimed[found->second]) return -1;
        claimed[found->second] = 1;
        return static_cast<std::ptrdiff_t>(found->second);
    };

    std::vector<const BranchEdit*> ordered;
    for (const BranchEdit& e : edits)
        ordered.push_back(&e);
    std::stable_sort(ordered.begin(), ordered.end(), [](const BranchEdit* a, const BranchEdit* b) {
        return depthOf(a->branch) < depthOf(b->branch);
    });

    const std::size_t grownSize = s.size();
    std::vector<char> remove(s.size(), 0);
    bool removing = false;
    for (const BranchEdit* e : ordered) {
        const std::ptrdiff_t found = resolve(*e);
        if (found < 0) {
            // A locked branch whose id is gone is grafted onto its parent, where it was.
            const auto parent = byId.find(parentId(e->branch));
            if (e->lock && !e->locked.empty() && parent != byId.end()) {
                const Branch& p = branches[parent->second];
                Index node = p.nodes.front();
                float best = std::numeric_limits<float>::max();
                for (Index k : p.nodes)
                    if (const float d = glm::length(s.position[at(k)] - e->lockedBase);
                        d < best && !remove[at(k)]) {
                        best = d;
                        node = k;
                    }
                if (!remove[at(node)]) {
                    report.grafted.emplace_back(e->branch, static_cast<Index>(s.size()));
                    graft(s, *e, node, s.position[at(node)]);
                    remove.resize(s.size(), 0);
                    ++report.applied;
                    ++report.reattached;
                    continue;
                }
            }
            // Inside a locked branch put back whole: carried by its kept geometry.
            const bool carried =
                std::any_of(report.grafted.begin(), report.grafted.end(),
                            [&](const auto& g) { return e->branch.rfind(g.first + ".", 0) == 0; });
            if (carried) {
                ++report.applied;
                continue;
            }
            report.orphaned.push_back(e->branch);
            continue;
        }
        ++report.applied;
        const Branch& b = branches[static_cast<std::size_t>(found)];
        if (b.id != e->branch) report.moved.emplace_back(e->branch, b.id);
        const Index first = b.nodes.front();
        const std::vector<char> in = subtree(s, first);
        const glm::vec3 base = s.position[at(b.baseNode >= 0 ? b.baseNode : first)];
        auto leavesOf = [&](auto&& f) {
            for (Leaf& leaf : s.leaves)
                if (leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < s.size() &&
                    in[at(leaf.node)])
                    f(leaf);
        };

        if (e->length != 1.0f) {
            std::vector<glm::vec3> delta(s.size(), glm::vec3(0.0f));
            glm::vec3 oldPrev = base, newPrev = base;
            std::vector<char> onChain(s.size(), 0);
            for (Index k : b.nodes) {
                const glm::vec3 p = s.position[at(k)];
                const glm::vec3 moved = newPrev + e->length * (p - oldPrev);
                delta[at(k)] = moved - p;
                onChain[at(k)] = 1;
                oldPrev = p;
                newPrev = moved;
            }
            for (std::size_t i = at(first); i < s.size(); ++i) {
                if (!in[i]) continue;
                if (!onChain[i]) delta[i] = delta[at(s.parent[i])];
                s.position[i] += delta[i];
            }
            leavesOf([&](Leaf& leaf) { leaf.position += delta[at(leaf.node)]; });
        }

        if (e->bend) {
            const glm::vec3 now = s.position[at(b.nodes.back())] - base;
            if (glm::length(now) > 1e-9f) {
                const glm::quat r = glm::rotation(glm::normalize(now), glm::normalize(*e->bend));
                for (std::size_t i = at(first); i < s.size(); ++i) {
                    if (!in[i]) continue;
                    s.position[i] = base + r * (s.position[i] - base);
                    s.orientation[i] = glm::normalize(r * s.orientation[i]);
                }
                leavesOf([&](Leaf& leaf) {
                    leaf.position = base + r * (leaf.position - base);
                    leaf.orientation = glm::normalize(r * leaf.orientation);
                });
            }
        }

        if (e->radius != 1.0f)
            for (std::size_t i = at(first); i < s.size(); ++i)
                if (in[i]) s.radius[i] *= e->radius;

        if (e->prune) {
            for (std::size_t i = 0; i < in.size(); ++i)
                if (in[i] && !remove[i]) {
                    remove[i] = 1;
                    ++report.prunedNodes;
                }
            removing = true;
        } else if (e->lock && !e->locked.empty() && b.baseNode >= 0) {
            // The kept geometry replaces what grew (it holds the other edits already).
            for (std::size_t i = 0; i < in.size(); ++i)
                if (in[i]) remove[i] = 1;
            report.grafted.emplace_back(e->branch, static_cast<Index>(s.size()));
            graft(s, *e, b.baseNode, base);
            remove.resize(s.size(), 0);
            removing = true;
        }
    }
    // A thicker branch never ends up thicker than the node it leaves from (the radius pass's
    // rule 3, shapeRadii): radii are clamped from the root up once any radius was raised.
    const bool thickened = std::any_of(edits.begin(), edits.end(),
                                       [](const BranchEdit& e) { return e.radius > 1.0f; });
    if (thickened)
        for (std::size_t i = 0; i < s.size(); ++i)
            if (const Index p = s.parent[i]; p >= 0 && s.radius[i] > s.radius[at(p)])
                s.radius[i] = s.radius[at(p)];
    if (removing) {
        // Kept nodes, grown and grafted, numbered in one run: what compact() gives them.
        std::vector<Index> renumber(remove.size(), -1);
        Index next = 0;
        for (std::size_t i = 0; i < remove.size(); ++i)
            if (!remove[i]) renumber[i] = next++;
        if (nodeMap)
            for (std::size_t i = 0; i < grownSize; ++i)
                (*nodeMap)[i] = renumber[i];
        for (auto& g : report.grafted)
            g.second = renumber[at(g.second)];
        compact(s, remove);
    }
    return report;
}

std::vector<Branch> editedBranches(const Skeleton& grown, const std::vector<BranchEdit>& edits,
                                   Skeleton* edited) {
    std::vector<Branch> branches = branchesOf(grown);
    if (edits.empty()) {
        if (edited) *edited = grown;
        return branches;
    }
    Skeleton s = grown;
    std::vector<Index> map;
    const BranchEditReport report = applyBranchEdits(s, edits, &map);
    std::vector<std::vector<Index>> kids(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.parent[i] >= 0) kids[at(s.parent[i])].push_back(static_cast<Index>(i));
    const std::vector<Index> cont = continuations(s, kids);
    // A branch from its (edited) first node: its chain walked again in the edited skeleton.
    auto measure = [&](Branch& b, Index first) {
        b.nodes.clear();
        for (Index k = first; k >= 0; k = cont[at(k)])
            b.nodes.push_back(k);
        b.baseNode = s.parent[at(first)] >= 0 && !b.parent.empty() ? s.parent[at(first)] : -1;
        b.base = s.position[at(b.baseNode >= 0 ? b.baseNode : first)];
        b.tip = s.position[at(b.nodes.back())];
        b.baseRadius = s.radius[at(first)];
        b.order = s.order[at(first)];
        b.length = 0.0f;
        for (Index k : b.nodes)
            if (s.parent[at(k)] >= 0)
                b.length += glm::length(s.position[at(k)] - s.position[at(s.parent[at(k)])]);
    };
    auto graftedAt = [&](const std::string& id) -> Index {
        for (const auto& [branch, first] : report.grafted)
            if (branch == id) return first;
        return -1;
    };
    std::vector<Branch> out;
    out.reserve(branches.size());
    for (Branch& b : branches) {
        Index first = map[at(b.nodes.front())];
        if (first < 0) first = graftedAt(b.id); // locked: its kept geometry
        if (first < 0) continue;
        measure(b, first);
        out.push_back(std::move(b));
    }
    // Locked branches grafted back onto their parent after their id was gone.
    for (const auto& [graftedId, first] : report.grafted) {
        const std::string& id = graftedId; // clang 14 captures no structured binding
        const bool listed =
            std::any_of(out.begin(), out.end(), [&id](const Branch& b) { return b.id == id; });
        if (listed) continue;
        Branch b;
        b.id = id;
        b.parent = parentId(id);
        measure(b, first);
        out.push_back(std::move(b));
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
        out[i].parentIndex = -1;
        for (std::size_t k = 0; k < i; ++k)
            if (out[k].id == out[i].parent) out[i].parentIndex = static_cast<std::int32_t>(k);
    }
    if (edited) *edited = std::move(s);
    return out;
}

void lockBranch(const Skeleton& grown, const std::vector<BranchEdit>& others, BranchEdit& edit) {
    std::vector<BranchEdit> rest;
    for (const BranchEdit& e : others)
        if (e.branch != edit.branch) rest.push_back(e);
    BranchEdit unlocked = edit;
    unlocked.lock = false;
    unlocked.locked.clear();
    unlocked.lockedLeaves.clear();
    rest.push_back(unlocked);
    Skeleton s = grown;
    std::vector<Index> map;
    applyBranchEdits(s, rest, &map);
    const std::vector<Branch> branches = branchesOf(grown);
    const auto b = std::find_if(branches.begin(), branches.end(),
                                [&](const Branch& x) { return x.id == edit.branch; });
    if (b == branches.end()) throw InvalidInput("there is no branch " + edit.branch);
    if (b->baseNode < 0)
        throw InvalidInput("branch " + edit.branch + " is a trunk: it cannot be locked");
    const Index first = map[at(b->nodes.front())];
    const Index baseNode = map[at(b->baseNode)];
    if (first < 0 || baseNode < 0) throw InvalidInput("branch " + edit.branch + " is pruned");
    const glm::vec3 base = s.position[at(baseNode)];
    const std::vector<char> in = subtree(s, first);
    std::vector<Index> local(s.size(), -1);
    edit.lock = true;
    edit.lockedBase = base;
    edit.locked.clear();
    edit.lockedLeaves.clear();
    for (std::size_t i = at(first); i < s.size(); ++i) {
        if (!in[i]) continue;
        LockedNode n;
        n.parent = static_cast<Index>(i) == first ? -1 : local[at(s.parent[i])];
        n.order = s.order[i];
        n.radius = s.radius[i];
        n.offset = s.position[i] - base;
        n.orientation = s.orientation[i];
        local[i] = static_cast<Index>(edit.locked.size());
        edit.locked.push_back(n);
    }
    for (const Leaf& leaf : s.leaves)
        if (leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < s.size() && in[at(leaf.node)])
            edit.lockedLeaves.push_back(
                {local[at(leaf.node)], leaf.size, leaf.position - base, leaf.orientation});
}

} // namespace sylva::skel
