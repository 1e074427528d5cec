"""The worksheet as pandoc writes it for HTML, Markdown and DOCX (issue 39, exports): the title once,
no LaTeX layout left as fenced divs in the Markdown, figures centred in the HTML, and a degree sign
on its number in the DOCX (it read 25.0□°: an empty base under the superscript)."""
import re
import zipfile

import pytest

from conftest import run_derive

RAMP = """\
id: ramp
title: A ball on a ramp
topic: rolling
parameters:
  M: {meaning: mass of the ball, unit: kg, range: [1, 3], sig_figs: 2}
  R: {meaning: radius of the ball, unit: m, value: 0.1}
  H: {meaning: height of the ramp, unit: m, value: 1.2}
  theta: {meaning: slope angle, unit: deg, value: 25°}
  g: {meaning: gravitational acceleration, unit: m/s^2, value: 9.81}
scene:
  surfaces:
    ramp: {incline: {angle: theta, height: H}}
  bodies:
    ball: {shape: sphere, mass: M, radius: R, on: ramp, contact: rolling}
  loads:
    - gravity: g
ask:
  a: {meaning: acceleration down the incline, of: ball.acceleration.down_incline, unit: m/s^2}
question: |
  A solid ball of mass {{ M }} rolls from rest down a ramp {{ H }} high at {{ theta }} to the horizontal.
"""


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    folder = tmp_path_factory.mktemp("pandoc")
    (folder / "ramp.yaml").write_text(RAMP)
    week = folder / "week.yaml"
    week.write_text(f"title: Week 4\nproblems: [{folder / 'ramp.yaml'}, string_wrapped_disk]\nvariants: 3\n"
                    "course: PHY141\ndue: 2026-12-01\n")
    done = run_derive("sheet", str(week), "--to", "md,html,docx", "--out", str(folder / "out"))
    assert done.returncode == 0, done.stderr
    return folder / "out"


def test_the_markdown_has_no_fenced_divs_and_its_title_once(built):
    text = (built / "worksheet.md").read_text()
    assert ":::" not in text and "<div" not in text
    assert text.count("Week 4") == 1 and text.count("PHY141") == 1  # the title in the metadata; the course once
    assert len(re.findall(r"^# Variant \d", text, re.M)) == 3
    assert "25.0^{\\circ}" in text and "{}^{\\circ}" not in text
    assert "PHY141" in text and "2026-12-01" in text  # pandoc read \quad 2026 as a dimension: PHY141-12-01


def test_the_html_shows_its_title_once_and_centres_its_figures(built):
    html = (built / "worksheet.html").read_text()
    assert html.split("<body>")[1].count(">Week 4<") == 1
    assert "div.center { text-align: center; }" in html and '<div class="center">' in html


def test_the_docx_degree_sign_rests_on_its_number(built):
    with zipfile.ZipFile(built / "worksheet.docx") as document:
        body = document.read("word/document.xml").decode()
    superscripts = re.findall(r"<m:sSup>.*?</m:sSup>", body)
    degrees = [s for s in superscripts if "∘" in s or "°" in s]
    assert degrees, "no degree sign in the DOCX"
    for s in degrees:
        base = re.search(r"<m:e>(.*?)</m:e>", s).group(1)
        assert "25" in base, s  # 25 carries the degree sign, not an empty box
