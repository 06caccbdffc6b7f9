#include "engine/growth/allocation.h"

#include <algorithm>
#include <functional>

#include "engine/util/parallelfor.h"

namespace sylva::growth {

namespace {

std::size_t sz(std::int32_t i) {
    return static_cast<std::size_t>(i);
}

} // namespace

void gatherLight(const MetamerTopology& t, std::span<const double> terminalLight,
                 std::span<const double> axillaryLight, std::span<double> gathered,
                 std::span<std::int32_t> internodes) {
    const std::size_t n = t.parent.size();
    for (std::size_t i = 0; i < n; ++i) {
        gathered[i] = (t.mainChild[i] < 0 ? terminalLight[i] : 0.0) +
                      (t.lateralChild[i] < 0 ? axillaryLight[i] : 0.0);
        internodes[i] = 1;
    }
    for (std::size_t i = n; i-- > 0;) {
        const std::int32_t p = t.parent[i];
        if (p < 0) continue;
        gathered[sz(p)] += gathered[i];
        internodes[sz(p)] += internodes[i];
    }
}

bool gatherLightAndMarkShed(const MetamerTopology& t, std::span<const double> terminalLight,
                            std::span<const double> axillaryLight,
                            std::span<const double> thresholdPerTree, std::span<double> gathered,
                            std::span<std::int32_t> internodes, std::span<std::uint8_t> marks,
                            std::vector<ShedSums>& scratch) {
    const std::size_t n = t.parent.size();
    scratch.resize(n);
    ShedSums* sums = scratch.data();
    const auto count = static_cast<std::int64_t>(n);
    auto own = [&](std::int64_t k) {
        const auto i = static_cast<std::size_t>(k);
        const double o = (t.mainChild[i] < 0 ? terminalLight[i] : 0.0) +
                         (t.lateralChild[i] < 0 ? axillaryLight[i] : 0.0);
        sums[i] = {o, o, 1, 1};
    };
    forEachIndex(count, count > 8192, own);
    bool any = false;
    // Reverse scan: when i is reached, all its descendants (higher indices) have added into it,
    // so its sums are final and its shedding can be decided before it adds to its parent.
    for (std::size_t i = n; i-- > 0;) {
        const ShedSums s = sums[i];
        gathered[i] = s.kept;
        internodes[i] = s.keptCount;
        const std::int32_t p = t.parent[i];
        if (p < 0) {
            marks[i] = 0;
            continue;
        }
        const bool lateral = t.lateralChild[sz(p)] == static_cast<std::int32_t>(i);
        const bool shedRoot = lateral && s.full < thresholdPerTree[t.tree[i]] * s.fullCount;
        marks[i] = static_cast<std::uint8_t>((shedRoot ? 1u : 0u) | (lateral ? 2u : 0u));
        any = any || shedRoot;
        ShedSums& up = sums[sz(p)];
        up.full += s.full;
        up.fullCount += s.fullCount;
        // A shed branch adds nothing (adding +0.0 would not change the bits of the sum: the
        // sums are ≥ 0, so x + 0.0 == x exactly).
        up.kept += shedRoot ? 0.0 : s.kept;
        up.keptCount += shedRoot ? 0 : s.keptCount;
    }
    return any;
}

Vigour allocateBorchertHonda(const MetamerTopology& t, std::span<const double> gathered,
                             std::span<const double> terminalLight,
                             std::span<const double> axillaryLight,
                             std::span<const AllocationParams> params) {
    Vigour out;
    allocateBorchertHonda(t, gathered, terminalLight, axillaryLight, params, out);
    return out;
}

void allocateBorchertHonda(const MetamerTopology& t, std::span<const double> gathered,
                           std::span<const double> terminalLight,
                           std::span<const double> axillaryLight,
                           std::span<const AllocationParams> params, Vigour& out) {
    const std::size_t n = t.parent.size();
    // metamer[i] is written by its parent (or as a root) before it is read; the bud arrays hold
    // 0 where the slot holds a child.
    out.metamer.resize(n);
    out.terminal.assign(n, 0.0);
    out.axillary.assign(n, 0.0);
    forEachBudVigourBorchertHonda(t, gathered, terminalLight, axillaryLight, params, out.metamer,
                                  [&](std::size_t i, bool lateral, double v) {
                                      (lateral ? out.axillary : out.terminal)[i] = v;
                                  });
}

Vigour allocateBorchertHondaNaive(const MetamerTopology& t, std::span<const double> terminalLight,
                                  std::span<const double> axillaryLight,
                                  std::span<const AllocationParams> params) {
    const std::size_t n = t.parent.size();
    // Light of a subtree by recursion over child pointers (memoized, else the oracle would be
    // quadratic); the per-bud path products below are the part the linear scan avoids.
    std::vector<double> memo(n, -1.0);
    std::function<double(std::int32_t)> light = [&](std::int32_t i) -> double {
        double& slot = memo[sz(i)];
        if (slot >= 0.0) return slot;
        const std::int32_t m = t.mainChild[sz(i)], l = t.lateralChild[sz(i)];
        slot =
            (m >= 0 ? light(m) : terminalLight[sz(i)]) + (l >= 0 ? light(l) : axillaryLight[sz(i)]);
        return slot;
    };
    Vigour out;
    out.metamer.assign(n, 0.0);
    out.terminal.assign(n, 0.0);
    out.axillary.assign(n, 0.0);
    std::vector<std::int32_t> path;
    for (std::size_t i = 0; i < n; ++i) {
        path.clear();
        for (std::int32_t j = static_cast<std::int32_t>(i); j >= 0; j = t.parent[sz(j)])
            path.push_back(j);
        const std::int32_t root = path.back();
        const AllocationParams& p = params[t.tree[sz(root)]];
        double v = p.alpha * light(root);
        for (std::size_t k = path.size() - 1; k > 0; --k) {
            const std::int32_t node = path[k], child = path[k - 1];
            const std::int32_t m = t.mainChild[sz(node)], l = t.lateralChild[sz(node)];
            const double qm = m >= 0 ? light(m) : terminalLight[sz(node)];
            const double ql = l >= 0 ? light(l) : axillaryLight[sz(node)];
            double vm = 0.0, vl = 0.0;
            detail::splitVigour(v, qm, ql, p.lambda, vm, vl);
            v = child == m ? vm : vl;
        }
        out.metamer[i] = v;
        const std::int32_t m = t.mainChild[i], l = t.lateralChild[i];
        const double qm = m >= 0 ? light(m) : terminalLight[i];
        const double ql = l >= 0 ? light(l) : axillaryLight[i];
        double vm = 0.0, vl = 0.0;
        detail::splitVigour(v, qm, ql, p.lambda, vm, vl);
        if (m < 0) out.terminal[i] = vm;
        if (l < 0) out.axillary[i] = vl;
    }
    return out;
}

Vigour allocatePriority(const MetamerTopology& t, std::span<const double> gathered,
                        std::span<const double> terminalLight,
                        std::span<const double> axillaryLight,
                        std::span<const AllocationParams> params) {
    Vigour out;
    allocatePriority(t, gathered, terminalLight, axillaryLight, params, out);
    return out;
}

void allocatePriority(const MetamerTopology& t, std::span<const double> gathered,
                      std::span<const double> terminalLight, std::span<const double> axillaryLight,
                      std::span<const AllocationParams> params, Vigour& out) {
    const std::size_t n = t.parent.size();
    out.metamer.assign(n, 0.0);
    out.terminal.assign(n, 0.0);
    out.axillary.assign(n, 0.0);
    std::size_t trees = 0;
    for (std::size_t i = 0; i < n; ++i)
        trees = std::max<std::size_t>(trees, t.tree[i] + 1u);

    // Bud key: 2·metamer + (0 terminal | 1 axillary).
    std::vector<std::vector<std::uint32_t>> buds(trees);
    for (std::size_t i = 0; i < n; ++i) {
        if (t.mainChild[i] < 0) buds[t.tree[i]].push_back(static_cast<std::uint32_t>(2 * i));
        if (t.lateralChild[i] < 0) buds[t.tree[i]].push_back(static_cast<std::uint32_t>(2 * i + 1));
    }
    auto budLight = [&](std::uint32_t key) {
        return (key & 1u) ? axillaryLight[key >> 1] : terminalLight[key >> 1];
    };
    std::vector<double> base(trees, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        if (t.parent[i] < 0) base[t.tree[i]] += params[t.tree[i]].alpha * gathered[i];

    for (std::size_t tr = 0; tr < trees; ++tr) {
        std::vector<std::uint32_t>& list = buds[tr];
        std::stable_sort(list.begin(), list.end(), [&](std::uint32_t a, std::uint32_t b) {
            return budLight(a) > budLight(b);
        });
        const AllocationParams& p = params[tr];
        const double span = std::max(1.0, p.kappa * static_cast<double>(list.size()));
        std::vector<double> qw(list.size());
        double sum = 0.0;
        for (std::size_t r = 0; r < list.size(); ++r) {
            const double f = std::min(1.0, static_cast<double>(r) / span);
            qw[r] = budLight(list[r]) * (p.wMax - (p.wMax - p.wMin) * f);
            sum += qw[r];
        }
        if (sum <= 0.0) continue;
        for (std::size_t r = 0; r < list.size(); ++r) {
            const double v = base[tr] * qw[r] / sum;
            ((list[r] & 1u) ? out.axillary : out.terminal)[list[r] >> 1] = v;
        }
    }
    for (std::size_t i = 0; i < n; ++i)
        out.metamer[i] = out.terminal[i] + out.axillary[i];
    for (std::size_t i = n; i-- > 0;)
        if (t.parent[i] >= 0) out.metamer[sz(t.parent[i])] += out.metamer[i];
}

std::vector<std::uint8_t> markShed(const MetamerTopology& t, std::span<const double> gathered,
                                   std::span<const std::int32_t> internodes,
                                   std::span<const double> thresholdPerTree) {
    const std::size_t n = t.parent.size();
    std::vector<std::uint8_t> removed(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = t.parent[i];
        if (p < 0) continue;
        if (removed[sz(p)]) {
            removed[i] = 1;
            continue;
        }
        const bool lateralRoot = t.lateralChild[sz(p)] == static_cast<std::int32_t>(i);
        if (lateralRoot && gathered[i] < thresholdPerTree[t.tree[i]] * internodes[i])
            removed[i] = 1;
    }
    return removed;
}

} // namespace sylva::growth
