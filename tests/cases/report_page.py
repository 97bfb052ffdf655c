#!/usr/bin/python3
"""report.html and the pictures of a run (issue 32, items 1 and 2), opened in a real headless browser
(Debian's chromium). Four small runs: the default case (2D linear static), the 3D flexure hinge, a 3D
modal cantilever and the large-rotation hinge (nonlinear, 4 steps). For each:

- the files appear (summary.json, report.html, the pictures), nothing is left under a temporary name,
  and each picture is well-formed SVG with coloured polygons;
- chromium renders the page: every picture decodes to a non-zero size (a script the test appends to a
  copy of the page reads naturalWidth/Height after load), and the screenshot holds the colour bands;
- the page's numbers are summary.json's: every quantity, every closed-form value and FE value (8
  digits, as printed), every validity warning's text, every geometry parameter;
- the peak printed on the picture is the summary's max_von_mises (4 digits).
A run with Output/Pictures=false writes neither pictures nor report.html.
"""
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402
from case_checks import check, finish  # noqa: E402

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
cases = os.path.join(root, "cases")
SVG = "{http://www.w3.org/2000/svg}"

runs = [
    ("2D linear static", "flexure_hinge.prm", [], ["picture.svg"]),
    ("3D linear static", "flexure_hinge_3d.prm", ["Geometry/Parameters/nb=1"], ["picture.svg"]),
    ("3D modal", "verification/modal_cantilever_3d.prm",
     ["Geometry/Parameters/nx=12", "Output/Fields=false"], ["mode_%d.svg" % k for k in range(1, 7)]),
    ("2D nonlinear static", "flexure_hinge_large_rotation.prm",
     ["Geometry/Parameters/nt=2", "Finite strain/Maximum step=0.25"], ["picture.svg", "load_displacement.svg"]),
]


def run(case, sets, out):
    command = ["mpirun", "-np", "2", solver_path(), os.path.join(cases, case), "--set", "Output/Directory=" + out]
    for s in sets:
        command += ["--set", s]
    return subprocess.run(command, capture_output=True, text=True, env=mpi_env(), timeout=600)


class Rows(html.parser.HTMLParser):
    """The data-* rows of the dumped DOM with the text of their cells, the images' attributes."""

    def __init__(self):
        super().__init__()
        self.rows, self.images, self.cells, self.row = [], [], None, None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "tr":
            self.row = (attrs, [])
        elif tag in ("td", "th") and self.row is not None:
            self.row[1].append("")
        elif tag == "img":
            self.images.append(attrs)

    def handle_endtag(self, tag):
        if tag == "tr" and self.row is not None:
            self.rows.append(self.row)
            self.row = None

    def handle_data(self, data):
        if self.row is not None and self.row[1]:
            self.row[1][-1] += data


def same(shown, value):
    """A value printed to 8 significant digits is the summary's value."""
    return abs(float(shown) - value) <= 1e-7 * abs(value) + 1e-300


def chromium(arguments, url):
    return subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                           "--virtual-time-budget=5000"] + arguments + [url],
                          capture_output=True, text=True, timeout=120)


def check_browser(name, out, summary):
    page = open(os.path.join(out, "report.html"), encoding="utf-8").read()
    check("http://" not in page.replace('xmlns="http://www.w3.org/2000/svg"', "") and "https://" not in page,
          "%s: report.html asks for nothing from the network" % name)
    # The test's own probe, appended to a copy: what the browser decoded for each picture.
    probe = os.path.join(out, "probe.html")
    with open(probe, "w", encoding="utf-8") as f:
        f.write(page.replace("</body>", "<script>window.addEventListener('load', () => { for (const i of "
                             "document.images) i.setAttribute('data-decoded', i.naturalWidth + 'x' + "
                             "i.naturalHeight); });</script></body>"))
    dom = chromium(["--dump-dom"], "file://" + probe)
    check(dom.returncode == 0 and "<table" in dom.stdout, "%s: chromium renders the page" % name)
    rows = Rows()
    rows.feed(dom.stdout)
    decoded = [i.get("data-decoded", "0x0") for i in rows.images]
    check(len(rows.images) > 0 and all(int(d.split("x")[0]) > 0 and int(d.split("x")[1]) > 0 for d in decoded),
          "%s: %d pictures decoded in the browser (%s)" % (name, len(rows.images), ", ".join(decoded)))
    shown = {a["data-quantity"]: cells for a, cells in rows.rows if "data-quantity" in a}
    q = summary["quantities"]
    listed = [k for k in q if not k.endswith(("_error_estimate", "_error_estimate_absolute"))]
    wrong = [k for k in listed if k not in shown or not same(shown[k][1], q[k])]
    check(len(listed) > 0 and not wrong, "%s: the page shows all %d quantities as summary.json holds them%s"
          % (name, len(listed), "" if not wrong else " (not: %s)" % ", ".join(wrong[:5])))
    compared = [(a, cells) for a, cells in rows.rows if "data-comparison" in a]
    ok = len(compared) == len(summary["comparisons"]) and all(
        a["data-comparison"] == c["quantity"] and same(cells[2], c["computed"]) and same(cells[3], c["reference"])
        for (a, cells), c in zip(compared, summary["comparisons"]))
    check(ok, "%s: %d closed-form comparisons shown with summary.json's values" % (name, len(compared)))
    text = re.sub(r"\s+", " ", html.unescape(re.sub(r"<[^>]+>", " ", dom.stdout)))
    warnings = [w for c in summary["comparisons"] for w in c["warnings"]]
    check(all(re.sub(r"\s+", " ", w) in text for w in warnings),
          "%s: all %d validity warnings are on the page" % (name, len(warnings)))
    params = {a["data-parameter"]: cells for a, cells in rows.rows if "data-parameter" in a}
    check(all(k in params and same(params[k][1], v) for k, v in summary["parameters"].items()),
          "%s: the geometry parameters are summary.json's" % name)
    screenshot = os.path.join(out, "page.png")
    chromium(["--screenshot=" + screenshot, "--window-size=1100,1400"], "file://" + probe)
    check(os.path.exists(screenshot) and coloured_pixels(screenshot) > 2000,
          "%s: the screenshot shows the coloured part (%d saturated pixels)"
          % (name, coloured_pixels(screenshot) if os.path.exists(screenshot) else 0))


def coloured_pixels(png):
    from PIL import Image
    image = Image.open(png).convert("RGB")
    return sum(1 for r, g, b in image.getdata() if max(r, g, b) - min(r, g, b) > 120)


def check_picture(name, path, summary):
    try:
        tree = ElementTree.parse(path)
    except ElementTree.ParseError as e:
        check(False, "%s: %s is well-formed SVG (%s)" % (name, os.path.basename(path), e))
        return
    svg = tree.getroot()
    painted = [p for p in svg.iter(SVG + "path") if p.get("color")] + list(svg.iter(SVG + "polyline"))
    check(svg.tag == SVG + "svg" and float(svg.get("width")) > 0 and len(painted) > 0,
          "%s: %s is SVG with %d painted elements" % (name, os.path.basename(path), len(painted)))
    q = summary["quantities"]
    if os.path.basename(path) == "picture.svg" and "max_von_mises" in q:
        text = " ".join("".join(t.itertext()) for t in svg.iter(SVG + "text"))
        m = re.search(r"peak von Mises stress ([-+0-9.eE]+)", text)
        check(m is not None and abs(float(m.group(1)) - q["max_von_mises"]) <= 5e-4 * abs(q["max_von_mises"]),
              "%s: the picture's peak %s is summary.json's max_von_mises %.6g"
              % (name, m.group(1) if m else "(none)", q["max_von_mises"]))


for name, case, sets, pictures in runs:
    out = tempfile.mkdtemp(prefix="report-")
    proc = run(case, sets, out)
    if not check(proc.returncode == 0, "%s: %s runs (exit %d) %s" % (name, case, proc.returncode, proc.stderr[-300:])):
        continue
    summary = json.load(open(os.path.join(out, "summary.json")))
    files = sorted(os.listdir(out))
    check(all(p in files for p in pictures + ["report.html"]) and not any(f.endswith(".partial") for f in files),
          "%s: %s written, nothing partial (%s)" % (name, ", ".join(pictures + ["report.html"]), ", ".join(files)))
    for p in pictures:
        if os.path.exists(os.path.join(out, p)):
            check_picture(name, os.path.join(out, p), summary)
    check_browser(name, out, summary)
    shutil.rmtree(out)

out = tempfile.mkdtemp(prefix="report-off-")
proc = run("flexure_hinge.prm", ["Output/Pictures=false", "Output/Fields=false"], out)
files = sorted(os.listdir(out)) if os.path.isdir(out) else []
check(proc.returncode == 0 and files == ["summary.json"],
      "Output/Pictures=false: only summary.json is written (%s)" % ", ".join(files))
shutil.rmtree(out, ignore_errors=True)
finish()
