"""`derive catalogue` (derive.publishing.catalogue): one self-contained HTML page of the library,
read back with lxml: every problem with its fields, statement, figure and asked quantities, and
nothing a problem file holds unescaped."""
import shutil

import lxml.html
import pytest

from conftest import ROOT, run_derive, write_problem
from derive.core import library
from derive.language import problem
from derive.publishing import figure


def _page(path) -> lxml.html.HtmlElement:
    return lxml.html.parse(str(path)).getroot()


@pytest.fixture(scope="module")
def library_page(tmp_path_factory):
    out = tmp_path_factory.mktemp("catalogue") / "catalogue.html"
    done = run_derive("catalogue", "--out", str(out))
    assert done.returncode == 0, done.stderr
    return out, done.stdout


@pytest.mark.slow  # the figures: one TeX run and pdftocairo for every problem (about a minute)
def test_every_library_problem_is_in_the_catalogue(library_page):
    out, said = library_page
    page = _page(out)
    problems = [problem.load(str(path)) for path in library.problem_files()]
    assert said.strip() == f"{out}: {len(problems)} problems" and len(problems) >= 150
    assert len(page.findall(".//article")) == len(problems)
    assert not page.xpath("//*[@src and not(starts-with(@src, 'data:'))] | //link[@href]")  # self-contained
    for p in problems:
        card = page.get_element_by_id(p.id)
        assert card.getparent().get("id") == f"topic-{p.topic}", p.id
        assert card.findtext("h3") == p.title
        meta = card.find_class("meta")[0].text_content()
        assert p.difficulty in meta and p.source in meta and [t.text for t in card.find_class("tag")] == list(p.tags)
        statement = card.find_class("statement")[0]
        assert statement.text_content().strip() and "{{" not in statement.text_content()
        assert len(card.find_class("given")[0].findall(".//li")) == len(p.parameters)
        asked = [li.text_content().replace("\u2019", "'") for li in card.find_class("asked")[0].findall(".//li")]
        assert len(asked) == len(p.asks)  # each with its meaning (pandoc's apostrophes curled)
        assert all(a.meaning in " ".join(t.split()) for a, t in zip(p.asks.values(), asked)), (p.id, asked)
        image = card.find(".//figure/img")
        assert (image is not None) == (figure.tikz(p) is not None), p.id
        if image is not None:
            assert image.get("src").startswith(("data:image/svg+xml;base64,", "data:image/png;base64,"))
    # MathML, not TeX source, for the symbols: the rolling sphere's theta is a <math> element
    sphere = page.get_element_by_id("rolling_incline").find_class("statement")[0]
    assert sphere.xpath(".//*[local-name()='math']") and "$" not in sphere.text_content()


HOSTILE = """\
id: hostile
title: A <script>alert('title')</script> & a disk
topic: torque
source: Book <b>bold</b> & "quoted"
difficulty: easy
tags: [disk]
parameters:
  M: {meaning: mass <img src=x onerror=alert(1)>, unit: kg, range: [1, 2]}
  R: {meaning: radius, unit: m, value: 0.2}
  tau: {meaning: torque, unit: N*m, value: 1}
scene:
  bodies:
    disk: {shape: disk, mass: M, radius: R, joint: fixed_axle}
  loads:
    - torque: {on: disk, magnitude: tau}
ask:
  alpha: {meaning: angular acceleration </li><script>x</script>, of: disk.angular_acceleration, unit: rad/s^2}
question: A disk of mass {{ M }} turns. Find alpha.
"""


def test_a_problem_files_text_is_escaped(tmp_path):
    folder = tmp_path / "library" / "torque"
    folder.mkdir(parents=True)
    path = write_problem(folder, HOSTILE)
    path.rename(folder / "hostile.yaml")
    out = tmp_path / "catalogue.html"
    done = run_derive("catalogue", "--out", str(out), "--no-figures", library=tmp_path / "library")
    assert done.returncode == 0, done.stderr
    page = _page(out)
    assert len(page.findall(".//script")) == 1 and not page.findall(".//b") and not page.findall(".//img")
    card = page.get_element_by_id("hostile")
    assert card.findtext("h3") == "A <script>alert('title')</script> & a disk"
    assert 'Book <b>bold</b> & "quoted"' in card.find_class("meta")[0].text_content()
    assert "mass <img src=x onerror=alert(1)>" in card.find_class("given")[0].text_content()
    assert "</li><script>x</script>" in " ".join(card.find_class("asked")[0].text_content().split())


def test_the_catalogue_replaces_only_its_own_page(tmp_path):
    library_copy = tmp_path / "library"
    shutil.copytree(ROOT / "problems" / "inertia", library_copy / "inertia")
    mine = tmp_path / "notes.html"
    mine.write_text("<p>my own notes</p>")
    refused = run_derive("catalogue", "--out", str(mine), "--no-figures", library=library_copy)
    assert refused.returncode == 2 and "not a catalogue derive wrote" in refused.stderr, refused.stderr
    assert mine.read_text() == "<p>my own notes</p>"
    out = tmp_path / "deep" / "catalogue.html"
    for _ in range(2):  # written, then replaced: derive's own page
        done = run_derive("catalogue", "--out", str(out), "--no-figures", library=library_copy)
        assert done.returncode == 0, done.stderr
    assert len(_page(out).findall(".//article")) == len(list((library_copy / "inertia").glob("*.yaml")))
    assert sorted(p.name for p in out.parent.iterdir()) == ["catalogue.html"]  # no temporary file left
