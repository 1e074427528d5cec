"""The HTML worksheet as a browser shows it: headless Chromium (Debian's, which scripts/install-tools
installs) loads a built worksheet.html, its math laid out as MathML and every figure loaded, and
takes a screenshot, kept in the test's folder (its path is printed)."""
import shutil
import subprocess

import lxml.html
import numpy
import pytest
from PIL import Image

from conftest import image_kind, run_derive

#: Marks each <img> and <math> with what the browser made of it, once the page has loaded.
PROBE = """<script>
addEventListener("load", () => {
  for (const img of document.images) img.dataset.loaded = img.complete && img.naturalWidth > 0 ? "yes" : "no";
  for (const math of document.querySelectorAll("math")) {
    math.dataset.display = getComputedStyle(math).display;
    math.dataset.width = math.getBoundingClientRect().width;
  }
});
</script>
"""


@pytest.fixture(scope="module")
def chromium():
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if not found:
        pytest.fail("chromium is not installed: scripts/install-tools installs it (as root: apt-get install -y "
                    "--no-install-recommends chromium)")
    return found


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("browser") / "demo"
    done = run_derive("sheet", "demo", "--variants", "2", "--to", "html", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out


def _browse(chromium, page, profile, *options) -> str:
    done = subprocess.run([chromium, "--headless", "--disable-gpu", "--no-sandbox", f"--user-data-dir={profile}",
                           "--virtual-time-budget=10000", *options, page.as_uri()],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    return done.stdout


def test_chromium_shows_the_math_and_every_figure(chromium, built, tmp_path):
    html = (built / "worksheet.html").read_text()
    probe = built / "probe.html"  # beside it, so that the figures' relative paths resolve the same
    probe.write_text(html.replace("</body>", PROBE + "</body>"))
    dom = lxml.html.fromstring(_browse(chromium, probe, tmp_path / "profile", "--dump-dom"))
    images = list(dom.iter("img"))
    assert len(images) == 2 * 3 and [i.get("data-loaded") for i in images] == ["yes"] * 6, \
        [(i.get("src"), i.get("data-loaded")) for i in images]
    maths = list(dom.iter("math"))
    assert maths and all("math" in m.get("data-display") and float(m.get("data-width")) > 0 for m in maths), \
        {(m.get("data-display"), m.get("data-width")) for m in maths}
    for annotation in dom.iter("annotation"):  # the TeX source MathML carries, never shown
        annotation.drop_tree()
    shown = dom.find("body").text_content()
    assert "\\" not in shown and "$" not in shown, "raw TeX in the page's text"

    screenshot = tmp_path / "worksheet.png"
    _browse(chromium, built / "worksheet.html", tmp_path / "profile", f"--screenshot={screenshot}",
            "--window-size=1000,2400", "--hide-scrollbars")
    print(f"screenshot of the worksheet in Chromium: {screenshot}")
    assert image_kind(screenshot.read_bytes()) == "png"
    with Image.open(screenshot) as picture:
        r, g, b = numpy.asarray(picture.convert("RGB")).astype(int).transpose(2, 0, 1)
    red = int(((r > 120) & (g < 80) & (b < 80)).sum())
    assert red > 50, "no figure painted: the figures' force arrows are the page's only red"
