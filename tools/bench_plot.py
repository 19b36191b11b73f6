"""Plot the error-versus-time results of `iblkit bench`.

Usage: python3 - RESULTS_JSON OUT_DIR < bench_plot.py   (script text on stdin)
Reads the bench's results.json ({"machine", "device", "date", "command",
"results": [{"environment", "method", "output", "samples", "device_ms",
"error_rms", "error_max", ...}]}) and writes into OUT_DIR (created if needed):

  specular_<environment>.png  RMS and max relative error against device time
  specular_summary.png        per method: worst RMS over environments against
                              the median device time, at each sample count
  lut.png                     max and RMS absolute error of the BRDF LUT
  irradiance.png              RMS relative error, one point per environment
                              and method (only when irradiance rows exist)
  size_curve.png              whole-process wall time and peak memory of a bake
                              against its base size, per method (only when the
                              document has "size_curve" rows: {"environment",
                              "method", "size", "wall_ms", "peak_mib", ...})

All axes are log-log; each method is one curve (points in increasing sample
count, annotated with it) and the Pareto frontier over all points of a panel is
drawn as a dashed black step line with its points ringed. Zero errors or times
are drawn a decade below the panel's smallest value, marked "(0 clipped)".
Each written file name (relative to OUT_DIR) is printed on its own line. On any
failure: one line on stderr, exit status 1, and no PNG is written (plots are
rendered to temporary names, renamed only once all of them have been).
"""
import json
import math
import os
import re
import statistics
import sys
import tempfile

DPI, SIZE = 110, (10, 4.5)
TINY = 1e-9  # stand-in for 0 on a log axis with no positive value at all
OUTPUTS = ("specular", "lut", "irradiance")
REL_RMS, REL_MAX = "RMS relative error (fraction)", "max relative error (fraction)"


class BenchError(Exception):
    pass


def new_figure():
    # Imported here so that a missing matplotlib is a one-line error like any other.
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    return Figure(figsize=SIZE, dpi=DPI)


def load(path):
    """(document, [row]) with the numeric fields checked and made floats."""
    try:
        with open(path, encoding="utf-8") as f:
            doc = json.load(f)
    except OSError as e:
        raise BenchError(f"cannot read {path}: {e.strerror}")
    except ValueError as e:
        raise BenchError(f"{path} is not valid JSON: {e}")
    rows = doc.get("results") if isinstance(doc, dict) else None
    if not isinstance(rows, list):
        raise BenchError(f"{path}: no 'results' list")
    good = []
    for i, r in enumerate(rows):
        if not isinstance(r, dict):
            raise BenchError(f"{path}: results[{i}] is not an object")
        if r.get("output") not in OUTPUTS:
            print(f"bench_plot: note: skipping results[{i}], output {r.get('output')!r}",
                  file=sys.stderr)
            continue
        row = {"output": r["output"], "method": str(r.get("method") or "(unnamed)"),
               "environment": str(r.get("environment") or "")}
        for key in ("samples", "device_ms", "error_rms", "error_max"):
            v = r.get(key)
            if type(v) not in (int, float) or not math.isfinite(v) or v < 0:
                raise BenchError(f"{path}: results[{i}] has no valid '{key}' ({v!r})")
            row[key] = float(v)
        good.append(row)
    if not good and not doc.get("size_curve"):
        raise BenchError(f"{path}: no specular, lut, irradiance or size curve results")
    return doc, good


def size_curve_rows(doc):
    """The cost curve's rows, their numbers checked."""
    rows = doc.get("size_curve") or []
    if not isinstance(rows, list):
        raise BenchError("'size_curve' is not a list")
    for i, r in enumerate(rows):
        for key in ("size", "wall_ms", "peak_mib"):
            v = r.get(key) if isinstance(r, dict) else None
            if type(v) not in (int, float) or not math.isfinite(v) or v <= 0:
                raise BenchError(f"size_curve[{i}] has no valid '{key}' ({v!r})")
    return rows


def size_curve_figure(doc, rows):
    """Time and memory against size, log-log: per method the median over the
    environments (thick), each environment (thin), and a dotted line growing as
    the texels do (size²) through the median's smallest size."""
    fig = new_figure()
    sizes = sorted({r["size"] for r in rows})
    methods = sorted({str(r["method"]) for r in rows})
    envs = sorted({str(r["environment"]) for r in rows})
    for ax, key, scale, label in zip(fig.subplots(1, 2), ("wall_ms", "peak_mib"), (1e-3, 1),
                                     ("whole-process wall time (s)", "peak memory (MiB)")):
        for i, method in enumerate(methods):
            color = f"C{i % 10}"
            at = [r for r in rows if r["method"] == method]
            for env in envs:
                pts = sorted((r["size"], r[key] * scale) for r in at if r["environment"] == env)
                ax.plot([p[0] for p in pts], [p[1] for p in pts], color=color, lw=0.6, alpha=0.35)
            med = [(s, statistics.median(r[key] * scale for r in at if r["size"] == s))
                   for s in sizes if any(r["size"] == s for r in at)]
            ax.plot([p[0] for p in med], [p[1] for p in med], color=color, lw=2, marker="o",
                    label=f"{method} (median of {len(envs)})")
            if key == "wall_ms" and med:
                s0, v0 = med[0]
                ax.plot(sizes, [v0 * (s / s0) ** 2 for s in sizes], color=color, ls=":", lw=1,
                        label=f"{method}: ∝ size²")
        ax.set(xscale="log", yscale="log", xlabel="base size (texels per face side)", ylabel=label)
        ax.set_xticks(sizes)
        ax.set_xticklabels([f"{s}²" for s in sizes])
        ax.minorticks_off()
        # 1, 2 and 5 of each decade, labelled: the curves may span less than one.
        from matplotlib.ticker import FormatStrFormatter, LogLocator
        ax.yaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
        ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.grid(True, which="major", alpha=0.5)
        ax.legend(fontsize=8)
    fig.suptitle("Whole bakes against size", fontsize=12)
    info = ", ".join(str(doc[k]) for k in ("device", "machine", "date") if doc.get(k))
    fig.text(0.995, 0.005, info, fontsize=7, color="0.4", ha="right", va="bottom")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    return fig


def clip_zeros(series):
    """Zeros cannot go on a log axis: put them a decade below the smallest
    positive value of the panel (or at TINY) and say so in the label."""
    every = [p for pts in series.values() for p in pts]

    def floor(vals):
        return min([v for v in vals if v > 0] or [TINY * 10]) / 10
    fx, fy = floor(p[0] for p in every), floor(p[1] for p in every)
    return {m: [(x or fx, y or fy, t + ("" if x and y else " (0 clipped)"))
                for x, y, t in pts] for m, pts in series.items()}


def pareto(points):
    """Non-dominated points (less time and less error is better), by time."""
    front = []
    for x, y, _ in sorted(points):
        if not front or y < front[-1][1]:
            front.append((x, y))
    return front


def panel(ax, series, colors, ylabel, title, connect=True):
    """One log-log panel; series is {method: [(seconds, error, label), ...]}."""
    everything = []
    for method, pts in sorted(clip_zeros(series).items()):
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=5,
                ls="-" if connect else "none", color=colors[method], label=method)
        for x, y, text in pts:
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(4, 4),
                        fontsize=7, color="0.25")
        everything += pts
    front = pareto(everything)
    ax.step([p[0] for p in front], [p[1] for p in front], where="post",
            color="k", ls="--", lw=1, label="Pareto frontier", zorder=1)
    ax.scatter([p[0] for p in front], [p[1] for p in front], s=130,
               facecolors="none", edgecolors="k", lw=1.2, zorder=3)
    ax.set(xscale="log", yscale="log", xlabel="device time (s)", ylabel=ylabel)
    ax.set_title(title, fontsize=10)
    ax.margins(0.12)
    ax.grid(True, which="major", alpha=0.5)
    ax.grid(True, which="minor", alpha=0.15)
    ax.legend(fontsize=8)


def figure(doc, title, panels):
    fig = new_figure()
    for ax, args in zip(fig.subplots(1, len(panels), squeeze=False)[0], panels):
        panel(ax, *args)
    fig.suptitle(title, fontsize=12)
    info = ", ".join(str(doc[k]) for k in ("device", "machine", "date") if doc.get(k))
    fig.text(0.995, 0.005, info, fontsize=7, color="0.4", ha="right", va="bottom")
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    return fig


def curves(rows, key, label_of=lambda r: str(int(r["samples"]))):
    """{method: [(seconds, error, label), ...]} in increasing sample count."""
    series = {}
    for r in sorted(rows, key=lambda r: (r["samples"], r["environment"])):
        series.setdefault(r["method"], []).append((r["device_ms"] / 1000, r[key], label_of(r)))
    return series


def summary(rows):
    """Per method and sample count: median time and worst RMS over environments."""
    series = {}
    for m, s in sorted({(r["method"], r["samples"]) for r in rows}):
        at = [r for r in rows if r["method"] == m and r["samples"] == s]
        series.setdefault(m, []).append((statistics.median(r["device_ms"] for r in at) / 1000,
                                         max(r["error_rms"] for r in at),
                                         f"{int(s)} (n={len(at)})"))
    return series


def build(doc, rows):
    """[(file name, Figure)] for every plot the rows allow."""
    colors = {m: f"C{i % 10}" for i, m in enumerate(sorted({r["method"] for r in rows}))}
    spec, lut, irr = ([r for r in rows if r["output"] == o] for o in OUTPUTS)
    plots, used = [], set()
    envs = sorted({r["environment"] for r in spec})
    for env in envs:
        name = re.sub(r"[^A-Za-z0-9_-]", "_", env) or "unnamed"
        while name in used:  # two names that sanitize alike
            name += "_"
        used.add(name)
        sel = [r for r in spec if r["environment"] == env]
        plots.append((f"specular_{name}.png", figure(
            doc, f"Specular prefilter, environment '{env}': luminance error vs device time",
            [(curves(sel, "error_rms"), colors, REL_RMS, "RMS error"),
             (curves(sel, "error_max"), colors, REL_MAX, "max error")])))
    if spec:
        plots.append(("specular_summary.png", figure(
            doc, f"Specular prefilter, all {len(envs)} environment(s): "
                 "worst RMS error vs median device time",
            [(summary(spec), colors, "worst RMS relative error (fraction)",
              "worst environment per sample count (n = environments)")])))
    if lut:
        plots.append(("lut.png", figure(
            doc, "BRDF LUT: absolute error vs device time",
            [(curves(lut, "error_max"), colors, "max absolute error", "max error"),
             (curves(lut, "error_rms"), colors, "RMS absolute error", "RMS error")])))
    if irr:
        plots.append(("irradiance.png", figure(
            doc, "Irradiance: RMS error vs device time, one point per environment",
            [(curves(irr, "error_rms", lambda r: r["environment"] or "(unnamed)"),
              colors, REL_RMS, "RMS error (labels: environment)", False)])))
    sized = size_curve_rows(doc)
    if sized:
        plots.append(("size_curve.png", size_curve_figure(doc, sized)))
    return plots


def main(argv):
    if len(argv) != 3:
        raise BenchError("usage: python3 - RESULTS_JSON OUT_DIR < bench_plot.py")
    doc, rows = load(argv[1])
    plots, out_dir = build(doc, rows), argv[2]
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as e:
        raise BenchError(f"cannot create {out_dir}: {e.strerror}")
    temps, umask = [], os.umask(0)
    os.umask(umask)
    try:
        for name, fig in plots:
            fd, tmp = tempfile.mkstemp(prefix=".bench_plot-", suffix=".tmp", dir=out_dir)
            temps.append(tmp)
            with os.fdopen(fd, "wb") as f:
                fig.savefig(f, format="png", dpi=DPI)
            os.chmod(tmp, 0o666 & ~umask)  # mkstemp creates it 0600
        for (name, _), tmp in zip(plots, temps):
            os.replace(tmp, os.path.join(out_dir, name))
            print(name)
    finally:
        for tmp in temps:
            if os.path.exists(tmp):
                os.remove(tmp)


if __name__ == "__main__":
    try:
        main(sys.argv)
    except Exception as e:  # one line, whatever went wrong
        msg = str(e) if isinstance(e, BenchError) else f"{type(e).__name__}: {e}"
        print("bench_plot: " + " ".join(msg.split()), file=sys.stderr)
        sys.exit(1)
