"""A solved problem as the command line prints it: text, LaTeX or the JSON contract.

The text is for a terminal: equations as sympy's unicode pretty-printer draws them, units as a
student reads them (m/s²). Values have the digits asked for, or, given `digits=None`, each
answer the significant figures its inputs support (`figures_supported`).

>>> from derive.language.problem import load
>>> result = solve(load("string_wrapped_disk"), {"m": "2", "M": "4", "R": "0.3"}, 6)
>>> result["answers"]["a"]["value"]
'-4.90500'
>>> solve(load("string_wrapped_disk"), {"m": "2", "M": "4", "R": "0.3"}, None)["answers"]["a"]["value"]
'-4.90'
"""
from __future__ import annotations

import json
import re

import sympy as sp

from derive.text.latex import latex_of, symbol_latex
from derive.publishing import letters, notation, wording
from derive.numbers import numeric
from derive.core import units
from derive.text.terminal import greek, indented, pretty
from derive.solution import answer_signs
from derive.solution.answers import Solution
from derive.mechanics.derivation import at_state
from derive.model.scene import DYNAMIC_KINDS
from derive.language.problem import DEFAULT_SIG_FIGS, Problem

_ROUTE_TITLES = {"lagrange": "Lagrange's method", "newton_euler": "Newton–Euler", "integration": "Integration"}


def route_title(route: str) -> str:
    """A heading for a route of derivation ("energy of the ball" stays as it is)."""
    return _ROUTE_TITLES.get(route, route[0].upper() + route[1:])


def figures_supported(solution: Solution, name: str) -> int:
    """The significant figures an answer's inputs support: its ask's `sig_figs`, else the fewest
    of the parameters its expression uses (each declares its own), else DEFAULT_SIG_FIGS."""
    problem = solution.problem
    if problem.asks[name].sig_figs:
        return problem.asks[name].sig_figs
    used = solution.expression(name).free_symbols
    return min((p.sig_figs for p in problem.parameters.values() if p.symbol in used), default=DEFAULT_SIG_FIGS)


def answer_values(solution: Solution, values: dict[sp.Symbol, sp.Expr], digits: int | None,
                  names: list[str] | None = None) -> dict[str, str | None]:
    """Each answer's value (or those `names`) in its declared unit, to `digits` significant
    digits (None: those its inputs support, `figures_supported`), the numbers of `derive solve`,
    after the problem's conditions are checked."""
    problem = solution.problem
    broken = solution.violated(values)
    if broken:
        raise problem.error("parameters", broken)
    never = solution.never_holds(values)
    if never:
        raise problem.error("scene", f"{never}, at every sample of the parameter ranges (give values with --set "
                                     "to answer one variant)")
    result = {}
    for name, ask in problem.asks.items():
        if names is not None and name not in names:
            continue
        expression = solution.expression(name)  # its errors (a time limit) say what they are
        try:
            shown = figures_supported(solution, name) if digits is None else digits
            result[name] = numeric.evaluate(units.in_unit(expression, ask.unit), values, shown)
        except (ValueError, ZeroDivisionError) as error:  # outside where the answer exists
            raise problem.error(f"ask.{name}", f"no real value at these parameters ({error})") from None
    return result


def _component(solution: Solution, name: str, values: dict, digits: int | None) -> str | None:
    """A quantity with a direction as the component along the file's axes (y up, counter-clockwise
    positive), for programs that read `derive solve`'s JSON; the value itself is its magnitude."""
    ask = solution.problem.asks[name]
    try:
        return numeric.evaluate(units.in_unit(solution.signed(name), ask.unit), values,
                                figures_supported(solution, name) if digits is None else digits)
    except (ValueError, ZeroDivisionError):
        return None


def solve(problem: Problem, overrides: dict[str, str] | None = None, digits: int | None = 15,
          solution: Solution | None = None) -> dict:
    """The JSON contract of `derive solve`: parameters, answers, equations of motion, checks;
    values to `digits` significant digits (None: each parameter its own, each answer what its
    inputs support). A Solution already derived for the problem may be passed in (it is the same
    derivation)."""
    solution = solution or Solution(problem)
    values = problem.values(overrides)
    parameters = {
        name: {
            "meaning": p.meaning,
            "unit": p.unit,
            "value": numeric.significant(units.in_unit(values[p.symbol], p.unit), p.sig_figs if digits is None else digits)
            if p.symbol in values else None,
        }
        for name, p in problem.parameters.items()
    }
    numbers = answer_values(solution, values, digits)
    answers = {}
    for name, ask in problem.asks.items():
        expression = solution.expression(name)
        answers[name] = {
            "meaning": ask.meaning,
            "expr": sp.sstr(expression),
            "latex": latex_of(expression),
            "unit": ask.unit,
            "value": numbers[name],
            "direction": answer_signs.direction(solution, name, values),
        }
        if solution.senses[name] is not None and not ask.magnitude:  # the component along the file's axes too
            answers[name]["component"] = _component(solution, name, values, digits)
    for name, ask in problem.asks.items():
        if ask.exact is not None:  # an approximation: its relative error at these parameters
            approximate, exact = answers[name]["value"], answers[ask.exact]["value"]
            error = None
            if approximate is not None and exact is not None and float(exact) != 0:
                ratio = numeric.evaluate(solution.expression(name) / solution.expression(ask.exact) - 1, values, 3)
                error = ratio
            answers[name]["approximation"] = {"exact": ask.exact, "relative_error": error}
    steps = notation.named(problem, solution, solution.steps())  # the names the worked solution prints
    kinds = {a.quantity.kind for a in problem.asks.values()}
    equations = {route: [sp.sstr(e) for e in route_equations]
                 for route, route_equations in equations_of_motion(solution).items()}
    checks = {c.name: {"passed": c.passed, "method": c.method, "detail": c.detail, "reading": c.reading}
              for c in solution.checks()}
    energy = ({k: sp.sstr(v) for k, v in solution.energy_ledger().items()} if kinds & DYNAMIC_KINDS else {})
    regimes = {}
    at_rest = {a.quantity.kind for a in problem.asks.values() if a.state is None}  # regimes are the placement's
    if at_rest & DYNAMIC_KINDS and solution.regimes[0].name:
        regimes = {"cases": [{"regime": r.name, "where": sp.sstr(w)}
                             for r, w in zip(solution.regimes, solution.regime_conditions())],
                   "applies": solution.regime_at(values)}
    for state, cases in solution.impact_regimes().items():  # a rough bounce asked in: grips or slides
        regimes[state] = {"cases": [{"regime": r.name, "where": sp.sstr(r.where)} for r in cases],
                          "applies": solution.impact_regime_at(state, values)}
    return {
        "id": problem.id,
        "title": problem.title,
        "source": problem.source,
        "parameters": parameters,
        "answers": answers,
        "regimes": regimes,
        "equations_of_motion": equations,
        "checks": checks,
        "energy": energy,
        "steps": {
            route: [{"sentences": [{"text": t.text(), "latex": t.latex()} for t in s.sentences],
                     "text": s.text, "latex": [latex_of(e) for e in s.equations]} for s in route_steps]
            for route, route_steps in steps.items()
        },
    }


def equations_of_motion(solution: Solution) -> dict[str, list[sp.Eq]]:
    """Each route's equations of motion in the reference configuration at rest (none where no
    ask is dynamic)."""
    if not {a.quantity.kind for a in solution.problem.asks.values()} & DYNAMIC_KINDS and not solution._needed_unknowns():
        return {}  # nothing asked reads the motion or its forces (a torque of a hinge's force does)
    rest = solution.coordinates.at_rest_in_reference()
    return {route: [at_state(e, rest) for e in d.at_rest_equations] for route, d in solution.derivations.items()}


def as_json(result: dict) -> str:
    return json.dumps(result, indent=2, ensure_ascii=False)


def _where(condition) -> tuple:
    """A regime's condition as the text prints it: "where ..." or, for the last, "otherwise"."""
    return ("otherwise",) if condition == sp.true else ("where ", condition)


def as_text(result: dict, solution: Solution, proof: bool = False) -> str:
    """The report for a terminal: `result` (the JSON contract) with the expressions of `solution`
    drawn by sympy's unicode pretty-printer and units as text reads them. Where the problem has a
    student's route (derive.solution.textbook), it is printed in place of the two routes' equations
    of motion, which `proof` adds (the checks compare them either way)."""
    lines = [f"{result['title']}  ({result['id']}{', ' + result['source'] if result['source'] else ''})", ""]
    words = wording.Wording(solution.problem)  # the documents' words: "the string", not the file's cord key
    windings = result["steps"].get("how the cords run", [])
    if windings:
        lines += ["How the cords run (in the placement, at the middle of the ranges):",
                  *(f"  {words(step['text'])}" for step in windings), ""]
    otherwise = letters.of_document(solution.problem, solution)  # the documents' letters: a length as ell beside L
    student = notation.printed(solution.problem, solution, solution.student_steps, otherwise) \
        if solution.student_steps else None
    renamed = [f"{pretty(otherwise[p.symbol])[0]} is the {p.meaning} (the file's {name}), so that {name} means one "
               "thing" for name, p in solution.problem.parameters.items() if p.symbol in otherwise]
    lines += [f"Printed here: {'; '.join(renamed)}.", ""] if renamed else []  # as the documents print it
    if student:
        lines += ["The solution, as a textbook writes it" + ("" if proof else " (the equations of motion by "
                                                            "Lagrange's method and Newton–Euler: --proof)") + ":"]
        for title, steps in student.items():
            lines.append(f"  {words(title)}")
            for step in steps:
                said = [line for s in step.sentences for line in words.sentence(s).text().splitlines()]
                lines += indented(said + ([greek(words(step.text)).rstrip(":") + ":"] if step.text else []), "    ")
                for equation in step.equations:
                    lines += indented(pretty(equation), "      ")
        lines.append("")
    for route, equations in equations_of_motion(solution).items() if proof or not student else ():
        lines.append(f"Equations of motion, {route_title(route)} (in the reference configuration, at rest):")
        said = [line for step in solution.derivations[route].steps for s in step.sentences for line in s.text().splitlines()]
        lines += indented(said) + ([""] if said else [])
        for equation in equations:
            lines += indented(pretty(equation))
        lines.append("")
    lines.append("Answers:")
    shown_forms = notation.shown_expressions(solution.problem, solution, otherwise)
    for name, a in result["answers"].items():
        unit = units.unicode_unit(a["unit"])
        value = f" = {a['value']}{' ' + unit if unit else ''}" if a["value"] is not None else \
            (f"  [{unit}]" if unit else "")
        lines += indented(pretty(sp.Symbol(name), " = ", shown_forms[name], value))
        said = a.get("direction") and not re.search(rf"\b{re.escape(a['direction'])}\b", a["meaning"])
        lines.append(f"    ({a['meaning']}{', ' + a['direction'] if said else ''})")  # not "energy lost, lost"
        if a.get("approximation") and a["approximation"]["relative_error"] is not None:
            lines.append(f"    approximates {a['approximation']['exact']}: relative error "
                         f"{a['approximation']['relative_error']}")
    if result["regimes"].get("cases"):
        lines += ["", "Friction regimes (each where those above do not hold):"]
        for regime, where in zip(solution.regimes, solution.regime_conditions()):
            lines += indented(pretty(f"{regime.name}: ", *_where(where)))
        if result["regimes"]["applies"]:
            lines.append(f"  at these parameters the body {result['regimes']['applies']}")
    started = {name: start for name, start in solution.starts.items() if start is not None} if solution.scene.states \
        else {}
    if started:  # the regime a segment's motion takes, which the equations above (held) do not show
        lines += ["", "How each segment starts (decided by friction, as at the middle of the ranges):"]
        for name, start in started.items():
            was = solution.scene.states[name].start
            lines.append(f"  to {name}: the {start.body} {start.taken.name} "
                         f"{'from the state ' + was if was else 'from rest at the placement'}"
                         + (", against kinetic friction" if start.taken.direction else ""))
    for state, cases in solution.impact_regimes().items():
        lines += ["", f"In the bounce {state} the contact (each where those above do not hold):"]
        for regime in cases:
            lines += indented(pretty(f"{regime.name}: ", *_where(regime.where)))
        if result["regimes"][state]["applies"]:
            lines.append(f"  at these parameters it {result['regimes'][state]['applies']}")
    if result["energy"] and (proof or not student):  # the ledger in the engine's coordinates: the proof's
        lines += ["", "Energy:"]
        for kind, expression in solution.energy_ledger().items():
            lines += indented(pretty(f"{kind.replace('_', ' ')}: ", expression))
    lines += ["", "Checks (the detail: derive check, or --format json):"]
    for name, c in result["checks"].items():
        lines.append(f"  [{'ok' if c['passed'] else 'FAILED'}] {name}: {c['reading']}")
    return "\n".join(lines)


def as_latex(result: dict) -> str:
    lines = [f"\\section*{{{result['title']}}}"]
    for route, steps in result["steps"].items():
        lines.append(f"\\subsection*{{{route_title(route)}}}")
        for step in steps:
            if step["sentences"]:
                lines.append(" ".join(s["latex"] for s in step["sentences"]))
                lines.append("")
            lines.append(step["text"] + (":" if step["latex"] else "" if step["text"].endswith(".") else "."))
            if step["latex"]:
                lines.append("\\begin{align*}")
                lines.append(" \\\\\n".join(aligned(eq) for eq in step["latex"]))
                lines.append("\\end{align*}")
    lines.append("\\subsection*{Answers}")
    lines.append("\\begin{align*}")
    lines.append(" \\\\\n".join(aligned(answer_latex(name, a)) for name, a in result["answers"].items()))
    lines.append("\\end{align*}")
    return "\n".join(lines)


def answer_latex(name: str, answer: dict) -> str:
    r"""An answer of the report as one LaTeX equation: its symbol, expression and value in its unit.

    >>> answer_latex("omega_0", {"latex": r"\sqrt{\frac{g}{L}}", "value": "3.13", "unit": "rad/s"})
    '\\omega_{0} = \\sqrt{\\frac{g}{L}} = 3.13\\,\\mathrm{rad}/\\mathrm{s}'
    """
    value = f" = {answer['value']}\\,{units.latex_unit(answer['unit'])}" if answer["value"] is not None else ""
    return f"{symbol_latex(name)} = {answer['latex']}{value}"


def aligned(latex_equation: str) -> str:
    """Put the alignment point at the first '=' of a LaTeX equation."""
    return latex_equation.replace("=", "&=", 1)
