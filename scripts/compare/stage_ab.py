#!/usr/bin/env python3
# One stage's time (GrowResult.timings_ms[stage]) of two builds of the Python module, interleaved
# seed by seed so that the shared machine's drift falls on both alike: two worker processes, one
# per module folder, answer in turn (which goes first alternates), the least of the rounds a
# seed, the mean over seeds. Run it in both orders; the same module against itself reads within
# about 0.6 % (docs/perf/geometry.md, sixth pass); with 4 rounds a stage reads within 1-2 %,
# so use 16 for changes of a few per cent.
#   python3 scripts/compare/stage_ab.py OLD_DIR NEW_DIR [rounds=4] [stage=grow] \
#       [species=presets/english-oak.json]
# OLD_DIR and NEW_DIR each hold one sylva*.so (e.g. copies of build/release/python).
import json, statistics, subprocess, sys


def worker(folder, species, stage):
    sys.path.insert(0, folder)
    import sylva
    sp = sylva.load_species(species)
    for s in range(3):
        sp.grow(990 + s)
    print("ready", flush=True)
    for line in sys.stdin:
        seed, reps = map(int, line.split())
        print(min(sp.grow(seed).timings_ms[stage] for _ in range(reps)), flush=True)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--worker":
        worker(sys.argv[2], sys.argv[3], sys.argv[4])
        return
    a, b = sys.argv[1], sys.argv[2]
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 4
    stage = sys.argv[4] if len(sys.argv) > 4 else "grow"
    species = sys.argv[5] if len(sys.argv) > 5 else "presets/english-oak.json"

    def start(folder):
        p = subprocess.Popen([sys.executable, __file__, "--worker", folder, species, stage],
                             stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
        assert p.stdout.readline().strip() == "ready"
        return p

    def ask(p, seed):
        # One grow an ask: a second grow of the same seed is the species' cached result, with
        # the same timings (a wasted grow, not a second sample); the rounds are the repeats.
        p.stdin.write(f"{seed} 1\n")
        p.stdin.flush()
        return float(p.stdout.readline())

    pa, pb = start(a), start(b)
    seeds = range(1000, 1048)
    ma = {s: float("inf") for s in seeds}
    mb = dict(ma)
    for r in range(rounds):
        for s in seeds:
            if (s + r) % 2:
                ma[s] = min(ma[s], ask(pa, s))
                mb[s] = min(mb[s], ask(pb, s))
            else:
                mb[s] = min(mb[s], ask(pb, s))
                ma[s] = min(ma[s], ask(pa, s))
    for p in (pa, pb):
        p.stdin.close()
        p.wait()
    mean_a = sum(ma.values()) / len(ma)
    mean_b = sum(mb.values()) / len(mb)
    print(json.dumps({"stage": stage, "a_ms": round(mean_a, 4), "b_ms": round(mean_b, 4),
                      "change_percent": round(100 * (mean_b - mean_a) / mean_a, 2),
                      "median_difference_ms": round(
                          statistics.median(mb[s] - ma[s] for s in seeds), 4)}))


main()
