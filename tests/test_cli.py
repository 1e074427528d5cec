"""The command-line contract of DESIGN.md: solve, inertia, list, exit codes, start-up."""
import json
import subprocess
import sys

import mpmath
import pytest

from conftest import ROOT, close


def close_to_digits(value: str, reference, digits: int = 15) -> bool:
    """A decimal string is correct to `digits` significant digits: within half a unit of the last."""
    return close(mpmath.mpf(value), mpmath.mpf(reference), digits)


def solve_json(derive, problem, *assignments, digits=15):
    args = ["solve", problem, "--format", "json", "--digits", str(digits)]
    for a in assignments:
        args += ["--set", a]
    done = derive(*args)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


@pytest.mark.parametrize("m, M", [("1.3", "2.9"), ("1e-12", "1"), ("1e12", "1"), ("0.999999999999", "1.000000000001")])
def test_disk_values_correct_to_15_digits(derive, m, M):
    result = solve_json(derive, "string_wrapped_disk", f"m={m}", f"M={M}", "R=0.37")
    mm, MM, g, R = mpmath.mpf(m), mpmath.mpf(M), mpmath.mpf("9.81"), mpmath.mpf("0.37")
    answers = result["answers"]
    assert close_to_digits(answers["a"]["value"], -2 * mm * g / (MM + 2 * mm))
    assert close_to_digits(answers["alpha"]["value"], -2 * mm * g / (R * (MM + 2 * mm)))
    assert close_to_digits(answers["T"]["value"], mm * g * MM / (MM + 2 * mm))
    assert result["checks"]["lagrange_vs_newton_euler"]["passed"] is True


def test_json_contract_keys(derive):
    result = solve_json(derive, "string_wrapped_disk")
    assert {"id", "title", "parameters", "answers", "equations_of_motion", "checks"} <= set(result)
    a = result["answers"]["a"]
    assert set(a) >= {"expr", "latex", "unit", "value"}
    assert a["value"] is None  # m, M, R have no value: only g does
    assert a["expr"] == "-2*g*m/(M + 2*m)"
    assert set(result["equations_of_motion"]) == {"lagrange", "newton_euler"}


def test_pendulum_values(derive):
    result = solve_json(derive, "compound_pendulum", "M=2", "Rcm=0.3", "I_cm=0.05", digits=20)
    omega = mpmath.sqrt(2 * mpmath.mpf("0.3") * mpmath.mpf("9.81") / (mpmath.mpf("0.05") + 2 * mpmath.mpf("0.09")))
    assert close_to_digits(result["answers"]["omega"]["value"], omega, 20)
    assert close_to_digits(result["answers"]["T"]["value"], 2 * mpmath.pi / omega, 20)


def test_set_converts_units(derive):
    grams = solve_json(derive, "string_wrapped_disk", "m=200 g", "M=1", "R=0.2")
    kilograms = solve_json(derive, "string_wrapped_disk", "m=0.2", "M=1", "R=0.2")
    assert grams["answers"] == kilograms["answers"]
    assert grams["parameters"]["m"]["value"] == "0.200000000000000"


def test_rod_inertia_values(derive):
    mid = solve_json(derive, "rod_midpoint", "m=3", "L=2")
    end = solve_json(derive, "rod_endpoint", "m=3", "L=2")
    assert mid["answers"]["I"]["value"] == "1.00000000000000"
    assert end["answers"]["I"]["value"] == "4.00000000000000"
    assert end["checks"]["parallel_axis"]["passed"] is True


def test_text_and_latex_formats(derive):
    text = derive("solve", "string_wrapped_disk", "--set", "m=1", "--set", "M=2", "--set", "R=0.5")
    assert text.returncode == 0
    assert "Equations of motion, Newton–Euler" in text.stdout and "a     = -2*g*m/(M + 2*m) = -4.90500000000000 m/s^2" in text.stdout
    latex = derive("solve", str(ROOT / "problems/torque/compound_pendulum.yaml"), "--format", "latex")
    assert latex.returncode == 0 and r"\begin{align*}" in latex.stdout and r"\omega" in latex.stdout


def test_inertia_command(derive):
    done = derive("inertia", "rod", "--axis", "end", "--set", "M=2", "--set", "L=3", "--format", "json")
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["I"] == "L**2*M/3" and result["ratio"] == "1/3" and result["value"] == "6.00000000000000"
    assert r"\int" in result["integral"]
    assert derive("inertia", "cube").returncode == 2


def test_list(derive):
    done = derive("list")
    assert done.returncode == 0
    ids = [line.split()[0] for line in done.stdout.splitlines()]
    assert {"rod_midpoint", "rod_endpoint", "string_wrapped_disk", "compound_pendulum"} <= set(ids)
    torque = derive("list", "--topic", "torque").stdout
    assert "string_wrapped_disk" in torque and "rod_midpoint" not in torque


@pytest.mark.parametrize("args, fragment", [
    (["solve", "no_such_problem"], "no problem file or library id"),
    (["solve", "string_wrapped_disk", "--set", "m"], "expected NAME=VALUE"),
    (["solve", "string_wrapped_disk", "--set", "q=2"], "has no parameter 'q'"),
    (["solve", "string_wrapped_disk", "--set", "m=2 m"], "m=2 m"),
    (["solve", "string_wrapped_disk", "--set", "m=__import__('os')"], "m="),
    (["solve", "missing/file.yaml"], "no such problem file"),
    (["solve", "beetle_lazy_susan", "--set", "v=-0.15"], "v must be positive"),
])
def test_bad_command_line_input_exits_2_with_one_line(derive, args, fragment):
    done = derive(*args)
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert fragment in done.stderr


def test_every_subcommand_has_help(derive):
    for command in ("solve", "inertia", "sheet", "list"):
        done = derive(command, "--help")
        assert done.returncode == 0 and "Usage" in done.stdout
    assert derive("--version").stdout.strip().endswith("0.1.0")


def test_help_does_not_import_sympy():
    code = ("import sys\nfrom derive.cli import main\ntry:\n    main(['--help'])\nexcept SystemExit:\n    pass\n"
            "print('sympy' in sys.modules, 'yaml' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.stdout.strip().splitlines()[-1] == "False False"


def test_output_into_a_closed_pipe_stops_quietly():
    from conftest import DERIVE
    done = subprocess.run(f"{DERIVE} list | head -1", shell=True, capture_output=True, text=True)
    assert done.stdout.count("\n") == 1 and "Error" not in done.stderr and "error" not in done.stderr
