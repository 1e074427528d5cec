r"""One letter, one kind of thing: the letters a worked solution prints otherwise where a problem's
parameter and another of its symbols would share one.

`derive.publishing.notation` refuses two symbols that print alike; this goes on to two that share a
letter and differ by a subscript but mean different kinds of thing: a rod's length L beside its
angular momentum L_z or L_O (the length is printed as \ell), an incline's angle theta beside a
body's turn theta_ball (the turn, a coordinate of the engine, is printed as phi_ball, or psi_ball
where a name of the file is phi), a radius R beside a joint's force R_x^axle (the force is
printed F_x^axle, or P_x^axle where a name of the file is F). The problem file keeps its names; its
answers' values and the keys are those derived.

>>> import sympy as sp
>>> L, theta, turn = sp.Symbol("L", positive=True), sp.Symbol("theta", positive=True), sp.Symbol("theta_ball")
>>> sorted(printed({"L": L, "theta": theta}, {"L_z"}, {turn, sp.Symbol("thetadot_ball")}).items(), key=str)
[(L, ell), (theta_ball, phi_ball), (thetadot_ball, phidot_ball)]
>>> printed({"R": sp.Symbol("R", positive=True)}, set(), {sp.Symbol("R_x^axle", real=True)})
{R_x^axle: F_x^axle}
>>> printed({"L": L}, {"Lmag"}, set())  # the ask prints |L|
{L: ell}
"""
from __future__ import annotations

import re
from collections.abc import Iterable, Mapping

import sympy as sp
from sympy.printing.conventions import split_super_sub
from sympy.printing.latex import modifier_dict

#: A parameter's letter, and what the documents print for it where another symbol shares that letter.
OTHERWISE = {"L": "ell"}
#: An engine coordinate's rotation angle (its rates too), and the letters it gives way to, in order.
TURN = re.compile(r"theta((?:d?dot)?)_(\w+)")
FREE = ("phi", "psi")
#: A joint's force (the engine's R_x^axle, or R_y as the student's route prints it), and its letters otherwise.
JOINT_FORCE = re.compile(r"R(_[xy](?:\^\w+)?)")
FORCE = ("F", "P")


#: sympy's printers' modifiers of a symbol's name (Lmag prints |L|, vbar v with a bar), longest first.
_MODIFIERS = re.compile("(" + "|".join(sorted(modifier_dict, key=len, reverse=True)) + ")+$")


def _letter(name: str) -> str:
    """The letter a symbol's name prints: its base less sympy's modifiers (Lmag, L_z: L)."""
    base = split_super_sub(name)[0]
    return _MODIFIERS.sub("", base) or base


def printed(parameters: Mapping[str, sp.Symbol], asks: Iterable[str], shown: Iterable[sp.Symbol]) -> dict[sp.Symbol, sp.Symbol]:
    """What the documents print for each symbol that shares a letter with another kind of thing:
    `parameters` by name, the names of the `asks`, the symbols the steps typeset (`shown`)."""
    shown = {s for s in shown if s not in parameters.values()}
    names = {*parameters, *asks, *(s.name for s in shown)}
    change = {}
    for name, symbol in parameters.items():
        if name in OTHERWISE and any(n != name and _letter(n) == name for n in names) \
                and not any(_letter(n) == OTHERWISE[name] for n in names):
            change[symbol] = sp.Symbol(OTHERWISE[name], **symbol.assumptions0)
    file_letters = {_letter(n) for n in (*parameters, *asks)}
    if "theta" in file_letters:
        free = next((f for f in FREE if f not in file_letters and not any(_letter(s.name) == f for s in shown)), None)
        for s in shown:
            if free and (turn := TURN.fullmatch(s.name)):
                change[s] = sp.Symbol(f"{free}{turn[1]}_{turn[2]}", **s.assumptions0)
    if "R" in parameters:
        free = next((f for f in FORCE if f not in file_letters and not any(_letter(s.name) == f for s in shown)), None)
        for s in shown:
            if free and s.name not in asks and (force := JOINT_FORCE.fullmatch(s.name)):
                change[s] = sp.Symbol(f"{free}{force[1]}", **s.assumptions0)
    return change


def of_document(problem, solution) -> dict[sp.Symbol, sp.Symbol]:
    """`printed` for a problem's worked solution: its parameters, its asks and every symbol its steps typeset."""
    from derive.publishing.notation import step_symbols

    steps = {**solution.steps(), **(solution.student_steps or {})}
    shown = step_symbols(s for route in steps.values() for s in route)
    return printed({n: p.symbol for n, p in problem.parameters.items()}, problem.asks, shown)
