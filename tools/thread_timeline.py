#!/usr/bin/env python3
"""Which thread ran when: a `perf record -a` of the viewer drawn as one row per thread, as SVG.

Each input is `perf script -F comm,pid,tid,time` of a system-wide recording of `arbor view`. The rows are the
viewer's main thread, lavapipe's queue thread (the viewer's busiest other thread), the rasteriser threads, the
X server and the idle CPUs; a row is filled in every time step where that thread was sampled. Several inputs
(before and after a change) are stacked, each under its label.

  perf record -a -F 2000 -o run.data -- arbor view black-tupelo --size 1280x720 --frames 20
  perf script -i run.data -F comm,pid,tid,time > run.txt
  tools/thread_timeline.py --panel "before" before.txt --panel "after" after.txt > timeline.svg
"""
import argparse
import collections
import html
import sys

ROW_HEIGHT, ROW_GAP, LABEL_WIDTH, TITLE_HEIGHT = 16, 4, 170, 22
COLOURS = {"viewer (main thread)": "#8c6bb1", "lavapipe queue thread": "#d95f02", "X server (Xvfb)": "#1b9e77",
           "idle CPU": "#bbbbbb"}
RASTER_COLOUR = "#377eb8"


def fail(message):
    """Bad input: say what and where, exit 2."""
    print(f"thread_timeline.py: {message}", file=sys.stderr)
    sys.exit(2)


def read_samples(path):
    """(comm, pid, tid, seconds) per sample."""
    samples = []
    try:
        text = open(path)
    except OSError as e:
        fail(f"{path}: {e.strerror}")
    with text:
        for number, line in enumerate(text, 1):
            words = line.split()
            if len(words) < 3 or not words[-1].endswith(":") or "/" not in words[-2]:
                continue
            try:
                pid, tid = (int(x) for x in words[-2].split("/"))
                seconds = float(words[-1][:-1])
            except ValueError:
                fail(f"{path}:{number}: expected 'comm pid/tid time:' (perf script -F comm,pid,tid,time), found {line.strip()!r}")
            samples.append((" ".join(words[:-2]), pid, tid, seconds))
    if not samples:
        fail(f"{path}: no samples (expected the output of perf script -F comm,pid,tid,time)")
    return samples


def rows_of(samples):
    """Row name per thread id, in drawing order."""
    viewer = [s for s in samples if s[0] == "arbor-engine"]
    if not viewer:
        fail("no samples of arbor-engine: record the viewer with perf record -a")
    main = viewer[0][1]
    others = collections.Counter(s[2] for s in viewer if s[2] != main)
    roles = {main: "viewer (main thread)"}
    if others:
        roles[others.most_common(1)[0][0]] = "lavapipe queue thread"
    for comm, _, tid, _ in samples:
        if comm.startswith("llvmpipe-"):
            roles[tid] = "rasteriser " + comm.split("-", 1)[1]
        elif comm == "Xvfb":
            roles[tid] = "X server (Xvfb)"
        elif comm == "swapper":
            roles[tid] = "idle CPU"
    order = ["viewer (main thread)", "lavapipe queue thread"] + sorted(r for r in set(roles.values()) if r.startswith("rasteriser"))
    order += ["X server (Xvfb)", "idle CPU"]
    return roles, [r for r in order if r in roles.values()]


def panel(samples, start_share, span, step):
    roles, order = rows_of(samples)
    viewer = [s[3] for s in samples if s[0] == "arbor-engine"]
    begin = viewer[0] + start_share * (viewer[-1] - viewer[0])
    bins = int(span / step)
    busy = {row: [0] * bins for row in order}
    for comm, _, tid, seconds in samples:
        k = int((seconds - begin) / step)
        if 0 <= k < bins and tid in roles:
            busy[roles[tid]][k] += 1
    return order, busy, bins


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--panel", nargs=2, action="append", metavar=("LABEL", "PERF_SCRIPT_TEXT"), required=True)
    parser.add_argument("--from", dest="start", type=float, default=0.7, help="where the window starts, as a share of the viewer's run (0..1)")
    parser.add_argument("--span", type=float, default=0.4, help="seconds shown")
    parser.add_argument("--step", type=float, default=0.002, help="seconds per time step")
    parser.add_argument("--pixels-per-step", type=int, default=2)
    args = parser.parse_args()
    if not 0.0 <= args.start < 1.0 or args.span <= 0.0 or args.step <= 0.0 or args.span / args.step > 20000:
        fail("--from must be in [0, 1), --span and --step positive, at most 20000 steps")

    panels = [(label, *panel(read_samples(path), args.start, args.span, args.step)) for label, path in args.panel]
    width = LABEL_WIDTH + int(args.span / args.step) * args.pixels_per_step + 10
    height = sum(TITLE_HEIGHT + len(order) * (ROW_HEIGHT + ROW_GAP) + 10 for _, order, _, _ in panels) + 24
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="DejaVu Sans" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    y = 0
    for label, order, busy, bins in panels:
        out.append(f'<text x="4" y="{y + 16}" font-weight="bold">{html.escape(label)}</text>')
        y += TITLE_HEIGHT
        for row in order:
            out.append(f'<text x="4" y="{y + 12}">{row}</text>')
            colour = RASTER_COLOUR if row.startswith("rasteriser") else COLOURS[row]
            k = 0
            while k < bins:  # runs of busy steps as one rectangle each
                if not busy[row][k]:
                    k += 1
                    continue
                first = k
                while k < bins and busy[row][k]:
                    k += 1
                x = LABEL_WIDTH + first * args.pixels_per_step
                out.append(f'<rect x="{x}" y="{y}" width="{(k - first) * args.pixels_per_step}" height="{ROW_HEIGHT}" fill="{colour}"/>')
            y += ROW_HEIGHT + ROW_GAP
        y += 10
    for ms in range(0, int(args.span * 1000) + 1, 50):  # a tick every 50 ms
        x = LABEL_WIDTH + ms / 1000 / args.step * args.pixels_per_step
        out.append(f'<line x1="{x}" y1="{y}" x2="{x}" y2="{y + 5}" stroke="black"/><text x="{x - 8}" y="{y + 18}" font-size="10">{ms} ms</text>')
    out.append("</svg>")
    print("\n".join(out))


if __name__ == "__main__":
    main()
