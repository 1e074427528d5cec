"""`derive inertia` as a user runs it: JSON keys, --about, --density, --tensor, help, and bad
input (exit 2, one line naming the option).

Bad input runs the console script, each case in its own process, all at once; the other
commands run in-process (click's runner), which shares the integrals cached by other tests.
"""
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import pytest
import sympy as sp
from click.testing import CliRunner

from conftest import run_derive
from derive.core import expr
from derive.model import inertia
from derive.cli import main
from derive.model.inertia import L, M, R, a, b, h

ERRORS = {  # run as processes of the console script: one case per option
    ("cube",): "SHAPE: unknown shape 'cube'",
    ("rod", "--axis", "middle"): "--axis middle: a rod has axes center, end",
    ("disk", "--about", "1,0"): "--about '1,0'",
    ("cylinder", "--set", "h=-3 cm"): "--set h=-3 cm: must be positive",
    ("disk", "--density", "cos(phi)"): "--density: density cos(phi) is negative",
    ("disk", "--density", "__import__('os').system('true')"): "--density",
}
MORE_ERRORS = {  # the same, in-process
    ("disk", "--axis", "0,0,0"): "--axis",
    ("disk", "--set", "R=0"): "--set R=0: must be positive",
    ("disk", "--set", "M=-2"): "--set M=-2: must be positive",
    ("rod", "--set", "L=2 kg"): "--set L=2 kg",
    ("disk", "--set", "q=1"): "--set q",
    ("annulus", "--set", "R1=2", "--set", "R2=1"): "--set R1",
    ("disk", "--density", "r*theta"): "--density 'r*theta'",
    ("disk", "--density", "0"): "--density: density 0 gives the disk no mass",
}


@pytest.fixture(scope="module")
def error_runs():
    with ThreadPoolExecutor(max_workers=2) as pool:
        return dict(zip(ERRORS, pool.map(lambda args: run_derive("inertia", *args), ERRORS)))


def invoke(*args: str):
    result = CliRunner().invoke(main, ["inertia", *args])
    assert result.exit_code == 0, (result.output, result.exception)
    return result.output


def output(*args: str) -> dict:
    return json.loads(invoke(*args, "--format", "json"))


def parsed(text: str, **extra) -> sp.Expr:
    """An expression the command printed, read back with the project's safe parser."""
    symbols = {"M": M, "L": L, "R": R, "h": h, "a": a, "b": b, **extra}
    return expr.parse(text, symbols)


def test_json_has_exactly_the_documented_keys_and_values():
    cone = output("cone", "--axis", "diameter", "--tensor", "--set", "M=2", "--set", "R=0.5", "--set", "h=1")
    assert list(cone) == ["shape", "axis", "integral", "mass", "I", "ratio", "tensor", "value"]
    assert cone["shape"] == "cone" and cone["axis"] == "diameter" and cone["mass"] == "M"
    assert parsed(cone["I"]) == 3 * M * (4 * R**2 + h**2) / 80
    assert r"\int" in cone["integral"] and r"\frac{h}{4}" in cone["integral"]  # the base at -h/4
    assert cone["value"] == "0.150000000000000"  # 3*2*(4*0.25 + 1)/80
    tensor = sp.Matrix([[parsed(e) for e in row] for row in cone["tensor"]])
    assert tensor == inertia.tensor("cone")
    assert output("cone")["tensor"] is None


@pytest.mark.parametrize("shape, axis, about, distance", [
    ("rod", "center", "L/2,0,0", L / 2),
    ("cylinder", "diameter", "0,0,h/2", h / 2),
    ("sphere", "symmetry", "R,0,0", R),
    ("box", "c", "a/2,b/2,0", sp.sqrt(a**2 + b**2) / 2),
    ("cone", "diameter", "0,0,3*h/4", 3 * h / 4),
])
def test_about_moves_the_axis_and_the_parallel_axis_theorem_holds(shape, axis, about, distance):
    shifted = parsed(output(shape, "--axis", axis, "--about", about)["I"], c=inertia.c)
    central = inertia.moment_of_inertia(shape, axis).I
    assert sp.simplify(shifted - inertia.parallel_axis(central, M, distance)) == 0


def test_tensor_about_the_given_point():
    box = output("box", "--axis", "c", "--about", "a/2,b/2,0", "--tensor")
    tensor = sp.Matrix([[parsed(e, c=inertia.c) for e in row] for row in box["tensor"]])
    theorem = inertia.parallel_axis_tensor(inertia.tensor("box"), M, (a / 2, b / 2, 0))
    assert sp.simplify(tensor - theorem) == sp.zeros(3)


def test_an_axis_given_by_direction():
    oblique = output("cylinder", "--axis", "1,0,1", "--about", "0,0,h/2")
    direct = inertia.moment_of_inertia("cylinder", ((0, 0, h / 2), (1, 0, 1))).I
    assert parsed(oblique["I"]) == direct
    assert oblique["axis"] == "along (1,0,1) through (0,0,h/2)"


def test_density_parameters_and_digits():
    disk = output("disk", "--density", "rho0*(r/R)^k", "--set", "rho0=3", "--set", "k=2", "--set", "R=50 cm",
                  "--digits", "6")
    k, rho0 = sp.symbols("k rho0", positive=True)
    assert parsed(disk["ratio"], k=k) == (k + 2) / (k + 4)
    assert sp.simplify(parsed(disk["mass"], k=k, rho0=rho0) - 2 * sp.pi * R**2 * rho0 / (k + 2)) == 0
    assert disk["value"] == "0.196350"  # 2 pi R^4 rho0/(k + 4) = pi/16


def test_point_mass_at_a_distance_in_text():
    text = invoke("point", "--axis", "0,0,1", "--about", "d,0,0", "--set", "M=2", "--set", "d=20 cm")
    assert text.splitlines()[1:] == ["         2    2", "  I = M⋅d  = d ⋅M", "  value: I = 0.0800000000000000 kg·m²"]


def test_latex_format():
    tex = invoke("rod", "--axis", "end", "--tensor", "--format", "latex")
    assert tex.startswith(r"\begin{align*}") and r"\frac{L^{2} M}{3}" in tex
    assert r"\mathbf{I} &= \left[\begin{matrix}" in tex


def test_help_lists_every_shape_with_its_axes_and_size_names():
    text = invoke("--help")
    lines = {line.split()[0]: line for line in text.splitlines() if line.strip() and line.split()[0] in inertia.SHAPES}
    assert set(lines) == set(inertia.SHAPES)
    for name, shape in inertia.SHAPES.items():
        assert ", ".join(shape.axes) in lines[name]
        for size, symbol in shape.sizes.items():
            assert f"{size} {symbol}" in lines[name]
    assert "Examples:" in text and "--density" in text and "--about" in text


@pytest.mark.parametrize("args", list(ERRORS))
def test_bad_input_exits_2_with_one_line_naming_the_option(error_runs, args):
    done = error_runs[args]
    assert done.returncode == 2, (done.stdout, done.stderr)
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert ERRORS[args] in done.stderr


@pytest.mark.parametrize("args", list(MORE_ERRORS))
def test_more_bad_input_exits_2_with_one_line(args):
    result = CliRunner().invoke(main, ["inertia", *args])
    assert result.exit_code == 2, result.output
    assert len(result.stderr.strip().splitlines()) == 1 and MORE_ERRORS[args] in result.stderr


def test_inertia_help_does_not_import_sympy():
    code = ("import sys\nfrom derive.cli import main\ntry:\n    main(['inertia', '--help'])\nexcept SystemExit:\n"
            "    pass\nprint('sympy' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip().splitlines()[-1] == "False"
