#!/usr/bin/env python3
"""Writes examples/results/README.md from the frontier data of scripts/report-frontier.sh (issue 12, part 3).

Each FRONTIER_DIR/<technique>.dat holds a header comment (scene, image size, reference, its noise floor) and
gnuplot index blocks: first brute force (`render --reference N`: N, seconds, RMSE, bytes), then one block per
effect setting (samples per pixel, seconds, RMSE, bytes). For every effect point (time t, RMSE e) the verdict is
the time brute force needs to reach the same RMSE, interpolated log-log between the two brute-force points whose
RMSEs bracket e: the effect wins at equal time where that time exceeds t (factor = brute time / t). Where even
brute force's largest N stays above e, the time is extrapolated along brute force's last segment; where brute force
at N = 1 is already below e, the effect loses if it took longer than N = 1 and is undecided (faster, less
accurate) otherwise.

    python3 scripts/frontier_verdicts.py FRONTIER_DIR OUT_MD --machine TEXT --command TEXT
"""
import argparse
import math
import os

# Technique id -> (what it shows, the report it belongs to, relative to examples/results/).
TECHNIQUES = {
    "filtering_plane": ("normal-map filtering ([Han07]: mip, toksvig, sh, vmf), receding plane, `gen bumps` 256^2",
                        "filtering/REPORT.md"),
    "filtering_spheres": ("normal-map filtering, spheres at three distances, `gen bumps` 256^2", "filtering/REPORT.md"),
    "demo": ("the built-in demo (README command (a)), every material switched to one effect", None),
    "crease": ("crease reconstruction ([Parilov05]) against plain bilinear MIP-mapped normals", "crease/REPORT.md"),
    "colormap": ("colour-map filtering ([Heitz13]): filtered against naive C(mean f)", "colormap/REPORT.md"),
    "glints": ("glint P-NDF ([Yan16]/[Wang20]) over the blended infinite microstructure", "glint/REPORT.md"),
}


def read(path):
    header, blocks, name = {}, [], None
    for line in open(path):
        line = line.strip()
        if line.startswith("# measured_seconds"):
            header["measured_seconds"] = line.split()[2]
        elif line.startswith("# technique"):
            words = line[2:].split()
            header = dict(zip(words[0::2], words[1::2]))
        elif line.startswith('"'):
            name = line.strip('"')
            blocks.append((name, []))
        elif line and not line.startswith("#"):
            label, x, seconds, rmse, size = line.split()
            blocks[-1][1].append((int(x), float(seconds), float(rmse), int(size)))
    return header, blocks


TIE = 1.2  # factors closer to 1 than this are within one-run timing noise on the shared machine


def positive(seconds):
    """render prints hundredths of a second: a 0.00 is under 0.005 s."""
    return max(seconds, 0.005)


def brute_time_for(rmse, brute):
    """(seconds brute force needs to reach rmse or None, how that was found)."""
    for k, (n, t, e, _) in enumerate(brute):
        if e <= rmse:
            if k == 0:
                return t, f"already at N = {n} (RMSE {e:.4f})"
            n0, t0, e0, _ = brute[k - 1]
            return log_log(rmse, (t0, e0), (t, e)), f"between {n0} x {n0} and {n} x {n}"
    (n0, t0, e0, _), (n, t, e, _) = brute[-2], brute[-1]
    if e < e0:  # extrapolated along the last segment
        return log_log(rmse, (t0, e0), (t, e)), f"extrapolated beyond {n} x {n} ({e:.4f} in {t:.2f} s)"
    return None, f"{n} x {n} rays give {e:.4f} in {t:.2f} s and no trend beyond"


def log_log(rmse, a, b):
    """The time at rmse on the line through a = (t, e) and b in log-log."""
    (t0, e0), (t1, e1) = a, b
    f = (math.log(rmse) - math.log(e0)) / (math.log(e1) - math.log(e0))
    return math.exp(math.log(positive(t0)) + f * (math.log(positive(t1)) - math.log(positive(t0))))


def verdict(seconds, rmse, brute):
    """(brute force's time over the effect's at the same RMSE, the sentence that says so)."""
    needed, how = brute_time_for(rmse, brute)
    seconds = positive(seconds)
    if needed is None:
        best = min(e for _, _, e, _ in brute)
        if rmse < best:
            how += f"; more accurate than every brute-force point (best {best:.4f}) at " \
                   f"{seconds / positive(brute[-1][1]):.1f}x the time of the largest"
        return 0.0, f"brute force: {how} -> undecided"
    factor = needed / seconds
    word = "**wins**" if factor > 1 else "loses"
    if 1 / TIE < factor < TIE:
        word += " (a tie within the timing noise)"
    text = f"brute force reaches it at {needed:.2f} s ({how}) -> {word} by {max(factor, 1 / factor):.1f}x"
    if how.startswith("already"):
        if factor > 1:  # faster than brute force's cheapest point, and less accurate than it
            return 0.0, f"brute force is {how} in {needed:.2f} s -> undecided (faster, less accurate)"
        text = f"brute force is {how} in {needed:.2f} s -> {word} by at least {1 / factor:.1f}x"
    return factor, text


def technique_section(tid, header, blocks):
    what, report = TECHNIQUES.get(tid, (tid, None))
    brute = blocks[0][1]
    floor = float(header["floor"])
    lines = [f"### {tid}: {what}", ""]
    if report:
        lines.append(f"Report: [{report}]({report}).")
    side = int(header.get("block", "1"))
    metric = "RMSE" if side == 1 else f"RMSE of {side} x {side} pixel block means"
    lines += [f"Scene `{header['scene']}` at {header['size']} pixels, measured {header.get('date', '?')} at load "
              f"average {header.get('load', '?')}; reference {header['reference']} x {header['reference']} rays "
              f"(seed 101, {header['reference_seconds']} s); measuring this technique took "
              f"{header.get('measured_seconds', '?')} s in all; its noise floor (seed 102 against it): {metric} "
              f"{floor:.4f}. Error: {metric}.", "",
              f"![{tid}: RMSE against time and bytes](frontier/{tid}.png)", "",
              f"![{tid}: pictures](frontier/{tid}_strip.png)", "",
              f"| setting | samples | time (s) | {metric} | bytes | against brute force at equal error |",
              "|---|---|---|---|---|---|"]
    for n, t, e, b in brute:
        lines.append(f"| brute force | {n} x {n} rays | {t:.2f} | {e:.4f} | {b} | |")
    wins, losses, undecided, bracketed = [], [], [], []
    for name, points in blocks[1:]:
        for spp, t, e, b in points:
            factor, text = verdict(t, e, brute)
            near_floor = " (under 1.5x the reference's own floor: the reference limits this measurement)" \
                if e < 1.5 * floor else ""
            lines.append(f"| {name} | {spp} spp | {t:.2f} | {e:.4f}{near_floor} | {b} | {text} |")
            (undecided if factor == 0 else wins if factor > 1 else losses).append((factor, name, spp, t, e))
            if factor > 0 and "already" not in text:
                bracketed.append((factor, name, spp, t, e))
    lines.append("")
    best = max(bracketed or wins + losses + undecided)  # best factor where brute force's time was bracketed
    summary = f"**Verdict ({tid})**: "
    if wins:
        summary += "the effect beats brute force at equal time at " + ", ".join(
            f"{name} {spp} spp ({f:.1f}x)"
            for f, name, spp, _, _ in sorted(wins, reverse=True)) + "; "
    else:
        summary += "no setting beats brute force at equal time; "
    if losses:
        summary += "it loses at " + ", ".join(f"{name} {spp} spp ({1 / f:.1f}x)" for f, name, spp, _, _ in
                                              sorted(losses, reverse=True)) + "."
    else:
        summary += "it loses nowhere."
    if undecided:
        summary += " Undecided (faster than brute force's cheapest point and less accurate, or no trend to " \
                   "extrapolate): " + ", ".join(f"{name} {spp} spp" for _, name, spp, _, _ in undecided) + "."
    f, name, spp, t, e = best
    summary += f" Best against brute force: {name} at {spp} spp, RMSE {e:.4f} in {t:.2f} s."
    lines += [summary, ""]
    return lines, (tid, wins, losses, undecided, best)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("frontier")
    parser.add_argument("out")
    parser.add_argument("--machine", required=True)
    parser.add_argument("--command", required=True)
    args = parser.parse_args()
    order = [t for t in TECHNIQUES if os.path.exists(os.path.join(args.frontier, t + ".dat"))]
    sections, summaries, headers = [], [], []
    for tid in order:
        header, blocks = read(os.path.join(args.frontier, tid + ".dat"))
        headers.append(header)
        lines, summary = technique_section(tid, header, blocks)
        sections += lines
        summaries.append(summary)
    results = os.path.dirname(os.path.abspath(args.out))
    reports = sorted(os.path.relpath(os.path.join(d, f), results) for d, _, files in os.walk(results)
                     for f in files if f in ("REPORT.md", "BENCH.md"))
    page = ["# Results: what accuracy costs in time", "",
            "<!-- generated by scripts/report-frontier.sh (scripts/frontier_verdicts.py); edit the scripts, "
            "not this page -->", "",
            "Every technique's own report:", ""]
    page += [f"- [{r}]({r})" for r in reports]
    page += ["", "## The frontier: each effect against brute force, at equal time", "",
             f"Command: `{args.command.strip()}` (Release build; measuring took "
             f"{sum(int(h.get('measured_seconds', 0)) for h in headers)} s in all, the load average while "
             f"each technique ran under its heading; with technique names it measures only those again and rewrites this "
             f"page from every technique's data). Machine: {args.machine}, shared with other engineers' jobs, so "
             "absolute times are inflated and noisy (one run per point: a 10-20% difference between two settings "
             "is within the noise); ratios within one run are what to read.",
             "",
             "Time is the time `microbake render` prints: loading the scene, its maps and assets, and rendering "
             "(process start-up and writing the image excluded), both threads. RMSE is of linear radiance "
             "(`microbake compare --format json`) against a converged brute-force reference (`render --reference "
             "R --seed 101`); brute force is `render --reference N` (N x N jittered rays per pixel with the raw "
             "maps, seed 0); effects are `render --spp S` (S stratified samples, each carrying its cell's "
             "footprint, anisotropic probes, `--max-probes 16`). Bytes: the baked .mbk files the render reads; for "
             "brute force and for plain normal mapping (no asset) the source maps' files. A verdict compares the "
             "effect's time with the time brute force needs for the same RMSE (log-log interpolation between "
             "brute-force points). Image sizes are chosen to keep the run near 12 minutes on 2 shared cores: "
             "the scenes are rendered at the size given under each heading (glints: the centre of the "
             "example's view at the example's pixel size, because a glint lookup costs in proportion to its "
             "footprint's texels, so a smaller image of the whole view would cost more per pixel, not less).",
             "", "## Summary", "", "| technique | wins at equal time (setting, samples per pixel) | loses | best against brute force (RMSE, time) |",
             "|---|---|---|---|"]
    for tid, wins, losses, undecided, best in summaries:
        f, name, spp, t, e = best
        page.append(f"| {tid} | "
                    f"{', '.join(f'{n} {s}' + (' (tie)' if f < TIE else '') for f, n, s, _, _ in sorted(wins, reverse=True)) or 'nowhere'} | "
                    f"{len(losses)} of {len(wins) + len(losses) + len(undecided)} | {name} {spp} spp ({e:.4f}, {t:.2f} s) |")
    page += ["", "A factor is brute force's time over the setting's at the same RMSE. \"plain\" is the scene without "
             "its effect (MIP-mapped normal mapping), the baseline the effect replaces. Multiscale synthesis "
             "(synth/REPORT.md) makes maps rather than shading them: it has no frontier here.", ""]
    page += sections
    open(args.out, "w").write("\n".join(page).rstrip() + "\n")


if __name__ == "__main__":
    main()
