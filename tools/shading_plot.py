"""Plot the shading bench's results: each recipe's error against roughness.

Usage: python3 - RESULTS_JSON OUT_DIR < shading_plot.py   (script text on stdin)
Reads the shading bench's results.json ({"grid": {"roughness", "rows"},
"environments": [{"name", "recipes": [{"recipe", "mean_relative_error",
"mean_relative_standard_error", "total_relative_error"}]}]}, each measure an
array over the grid's spheres, row after row) and writes into OUT_DIR (created
if needed):

  summary.png        per material (a panel each): the worst over environments of
                     each sphere's mean per-pixel error, against roughness, one
                     curve per recipe, with the target (3 % above the noise)
  <environment>.png  per metal (gold, silver): the mean per-pixel error and the
                     summed error against roughness, one curve per recipe

Each written file name (relative to OUT_DIR) is printed on its own line. On any
failure: one line on stderr, exit status 1, and no PNG is written (plots are
rendered to temporary names, renamed only once all of them have been).
"""
import json
import os
import sys
import tempfile

DPI = 72
FLOOR = 1e-3  # a mean error of 0.1 % or less is drawn at 0.1 % on the log axis


def spheres_of(results, recipe):
    """The recipe's spheres as dictionaries: material, roughness and each measure."""
    grid = results["grid"]
    columns = len(grid["roughness"])
    spheres = []
    for i in range(len(recipe["mean_relative_error"])):
        sphere = {"material": grid["rows"][i // columns], "roughness": grid["roughness"][i % columns]}
        for key in ("mean_relative_error", "mean_relative_standard_error", "total_relative_error"):
            sphere[key] = recipe[key][i]
        spheres.append(sphere)
    return spheres


def recipes_of(results):
    names = []
    for environment in results["environments"]:
        for recipe in environment["recipes"]:
            if recipe["recipe"] not in names:
                names.append(recipe["recipe"])
    return names


def curve(spheres, material, key):
    points = sorted((s["roughness"], s[key]) for s in spheres if s["material"] == material)
    return [p[0] for p in points], [p[1] for p in points]


def excess(sphere):
    return sphere["mean_relative_error"] - 0.8 * sphere["mean_relative_standard_error"]


def summary_plot(plt, results, path):
    materials = results["grid"]["rows"]
    figure, axes = plt.subplots(1, len(materials), figsize=(4 * len(materials), 4), sharey=True)
    for axis, material in zip(axes, materials):
        for name in recipes_of(results):
            worst = {}
            for environment in results["environments"]:
                for recipe in environment["recipes"]:
                    if recipe["recipe"] != name:
                        continue
                    for sphere in spheres_of(results, recipe):
                        if sphere["material"] == material:
                            r = sphere["roughness"]
                            worst[r] = max(worst.get(r, 0.0), excess(sphere))
            xs = sorted(worst)
            axis.plot(xs, [max(100 * worst[x], 100 * FLOOR) for x in xs], marker="o", markersize=3, label=name)
        axis.axhline(3.0 if material != "glass" else 20.0, color="black", linestyle="--", linewidth=1)
        axis.set_yscale("log")
        axis.set_title(material)
        axis.set_xlabel("roughness")
        axis.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("worst mean |error| above noise, % (log)")
    axes[-1].legend(fontsize=7, loc="lower right")
    figure.suptitle("Worst over every environment, per sphere; dashed: the target")
    figure.tight_layout()
    figure.savefig(path, dpi=DPI)
    plt.close(figure)


def environment_plot(plt, results, environment, path):
    metals = [m for m in ("gold", "silver") if m in results["grid"]["rows"]]
    figure, axes = plt.subplots(2, len(metals), figsize=(6 * len(metals), 7), squeeze=False)
    for column, material in enumerate(metals):
        for recipe in environment["recipes"]:
            spheres = spheres_of(results, recipe)
            xs, means = curve(spheres, material, "mean_relative_error")
            _, totals = curve(spheres, material, "total_relative_error")
            axes[0][column].plot(xs, [max(100 * m, 100 * FLOOR) for m in means], marker="o", markersize=3, label=recipe["recipe"])
            axes[1][column].plot(xs, [100 * t for t in totals], marker="o", markersize=3, label=recipe["recipe"])
        axes[0][column].set_yscale("log")
        axes[0][column].set_title(f"{material}: mean |error| per pixel, %")
        axes[1][column].set_title(f"{material}: summed error, %")
        axes[1][column].axhspan(-2, 2, color="green", alpha=0.1)
        for row in (0, 1):
            axes[row][column].set_xlabel("roughness")
            axes[row][column].grid(True, which="both", alpha=0.3)
    axes[0][-1].legend(fontsize=7)
    figure.suptitle(environment["name"])
    figure.tight_layout()
    figure.savefig(path, dpi=DPI)
    plt.close(figure)


def main():
    if len(sys.argv) != 3:
        raise ValueError("usage: python3 - RESULTS_JSON OUT_DIR < shading_plot.py")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with open(sys.argv[1], encoding="utf-8") as stream:
        results = json.load(stream)
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    drawn = []
    with tempfile.TemporaryDirectory(dir=out) as scratch:
        summary_plot(plt, results, os.path.join(scratch, "summary.png"))
        drawn.append("summary.png")
        for environment in results["environments"]:
            name = environment["name"] + ".png"
            environment_plot(plt, results, environment, os.path.join(scratch, name))
            drawn.append(name)
        for name in drawn:
            os.replace(os.path.join(scratch, name), os.path.join(out, name))
    for name in drawn:
        print(name)


if __name__ == "__main__":
    try:
        main()
    except Exception as error:  # one line, whatever went wrong
        print(f"shading_plot.py: {error}", file=sys.stderr)
        sys.exit(1)
