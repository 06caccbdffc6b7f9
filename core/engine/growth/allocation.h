#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace sylva::growth {

/// The metamers of one or more trees as a binary tree in struct-of-arrays form, parents before
/// children (parent[i] < i). Each metamer (internode + leaf + axillary bud) ends in a node where
/// its axis continues (the main child, or the terminal bud when the axis ends there) and where
/// its lateral branch starts (the lateral child, or the axillary bud when it has not grown).
struct MetamerTopology {
    std::span<const std::int32_t> parent;       ///< −1 for the first metamer of a tree
    std::span<const std::int32_t> mainChild;    ///< −1: the axis ends in the terminal bud
    std::span<const std::int32_t> lateralChild; ///< −1: the axillary bud has not grown
    std::span<const std::uint16_t> tree;        ///< index of the tree the metamer belongs to
};

/// Basipetal pass (one reverse scan): \p gathered[i] = light of all buds carried by metamer i
/// and its descendants, \p internodes[i] = number of metamers in that subtree (i included).
/// Bud light is 0 for a slot that holds a child or a dead bud.
void gatherLight(const MetamerTopology& topology, std::span<const double> terminalLight,
                 std::span<const double> axillaryLight, std::span<double> gathered,
                 std::span<std::int32_t> internodes);

/// Subtree sums before and after shedding (gatherLightAndMarkShed's scratch, one per metamer,
/// kept together so a child adds into one cache line of its parent).
struct ShedSums {
    double full, kept;
    std::int32_t fullCount, keptCount;
};

/// gatherLight and markShed in one reverse scan, for the growth loop. Fills \p gathered and
/// \p internodes as gatherLight would for the tree that remains after shedding (the subtree
/// sums of the shed lateral branches left out, in the same order, so the values are bit for bit
/// those of gatherLight over the remaining metamers) and \p marks: bit 0 for the roots of shed
/// branches (a lateral child whose full subtree has gathered / internodes below its tree's
/// threshold, as in markShed), bit 1 for every lateral child. Everything under a marked root is
/// shed too; the caller propagates that (parents before children). \p scratch is reused
/// between calls. Returns whether any root is marked.
bool gatherLightAndMarkShed(const MetamerTopology& topology, std::span<const double> terminalLight,
                            std::span<const double> axillaryLight,
                            std::span<const double> thresholdPerTree, std::span<double> gathered,
                            std::span<std::int32_t> internodes, std::span<std::uint8_t> marks,
                            std::vector<ShedSums>& scratch);

/// Per-tree constants of the allocation models (index = MetamerTopology::tree).
struct AllocationParams {
    double alpha = 2.0;  ///< v_base = α·Q_base, (0, 100]
    double lambda = 0.5; ///< Borchert–Honda apical control, [0, 1]; 0.5 = no bias
    double wMin = 0.06;  ///< priority model: weight of the least lit buds, [0, wMax]
    double wMax = 1.0;   ///< priority model: weight of the best lit bud, (0, 10]
    double kappa = 0.5;  ///< priority model: fraction of buds over which w falls, (0, 1]
};

/// Vigour of every metamer (the resource flowing through its internode) and of every bud.
struct Vigour {
    std::vector<double> metamer, terminal, axillary;
};

namespace detail {
/// Split of vigour \p v between the axis (light \p qm) and the lateral branch (light \p ql).
inline void splitVigour(double v, double qm, double ql, double lambda, double& vm, double& vl) {
    const double wm = lambda * qm;
    const double wl = (1.0 - lambda) * ql;
    const double d = wm + wl;
    if (d <= 0.0) {
        vm = vl = 0.0;
        return;
    }
    vm = v * wm / d;
    vl = v * wl / d;
}
} // namespace detail

/// Borchert–Honda's forward scan (see allocateBorchertHonda) with the vigour of each bud handed
/// to \p bud(i, lateral, v), terminal before axillary, in metamer order, for every slot that
/// holds a bud (not a child): the growth loop plans its shoots from it in the same pass instead
/// of storing every bud's vigour and reading it back. \p metamer receives every metamer's vigour.
template <class BudFn>
void forEachBudVigourBorchertHonda(const MetamerTopology& t, std::span<const double> gathered,
                                   std::span<const double> terminalLight,
                                   std::span<const double> axillaryLight,
                                   std::span<const AllocationParams> params,
                                   std::span<double> metamer, BudFn&& bud) {
    const std::size_t n = t.parent.size();
    for (std::size_t i = 0; i < n; ++i) {
        const AllocationParams& p = params[t.tree[i]];
        if (t.parent[i] < 0) metamer[i] = p.alpha * gathered[i];
        const std::int32_t m = t.mainChild[i], l = t.lateralChild[i];
        const double qm = m >= 0 ? gathered[static_cast<std::size_t>(m)] : terminalLight[i];
        const double ql = l >= 0 ? gathered[static_cast<std::size_t>(l)] : axillaryLight[i];
        double vm = 0.0, vl = 0.0;
        detail::splitVigour(metamer[i], qm, ql, p.lambda, vm, vl);
        if (m >= 0)
            metamer[static_cast<std::size_t>(m)] = vm;
        else
            bud(i, false, vm);
        if (l >= 0)
            metamer[static_cast<std::size_t>(l)] = vl;
        else
            bud(i, true, vl);
    }
}

/// Borchert–Honda allocation, one forward scan: v_root = α·Q_root; at each node the vigour v is
/// split into v_m = v·λQ_m / (λQ_m + (1−λ)Q_l) for the axis and v_l = v·(1−λ)Q_l / (…) for the
/// lateral branch (Q from gatherLight). A node whose two sides both have Q = 0 passes nothing.
Vigour allocateBorchertHonda(const MetamerTopology& topology, std::span<const double> gathered,
                             std::span<const double> terminalLight,
                             std::span<const double> axillaryLight,
                             std::span<const AllocationParams> params);
/// The same, into \p out (its buffers are reused: no allocation once they are large enough).
void allocateBorchertHonda(const MetamerTopology& topology, std::span<const double> gathered,
                           std::span<const double> terminalLight,
                           std::span<const double> axillaryLight,
                           std::span<const AllocationParams> params, Vigour& out);

/// The same model computed the slow way (test oracle and benchmark baseline): the vigour of
/// each bud is v_base times the product of the split fractions along its path to the root
/// (O(n·depth)), with Q from a recursion over the child pointers.
Vigour allocateBorchertHondaNaive(const MetamerTopology& topology,
                                  std::span<const double> terminalLight,
                                  std::span<const double> axillaryLight,
                                  std::span<const AllocationParams> params);

/// Priority model: the buds of each tree are ranked by light (ties: lower metamer first,
/// terminal before axillary); the weight falls linearly from w_max (rank 0) to w_min at rank
/// κ·N and stays w_min below; bud vigour = v_base·Q·w / Σ Q·w. Metamer vigour is the sum over
/// its subtree, so vigour is conserved at every fork as in Borchert–Honda.
Vigour allocatePriority(const MetamerTopology& topology, std::span<const double> gathered,
                        std::span<const double> terminalLight,
                        std::span<const double> axillaryLight,
                        std::span<const AllocationParams> params);
/// The same, into \p out (its buffers are reused).
void allocatePriority(const MetamerTopology& topology, std::span<const double> gathered,
                      std::span<const double> terminalLight, std::span<const double> axillaryLight,
                      std::span<const AllocationParams> params, Vigour& out);

/// Shedding: marks for removal every lateral branch (a metamer that is its parent's lateral
/// child) whose gathered light per internode, gathered[i] / internodes[i], is below the
/// threshold of its tree, together with everything it carries. The axis from a tree's first
/// metamer is never shed. One forward scan; returns 1 for removed metamers. (The growth loop
/// uses gatherLightAndMarkShed; this plain form is its test oracle.)
std::vector<std::uint8_t> markShed(const MetamerTopology& topology,
                                   std::span<const double> gathered,
                                   std::span<const std::int32_t> internodes,
                                   std::span<const double> thresholdPerTree);

} // namespace sylva::growth
