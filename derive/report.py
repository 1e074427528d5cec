"""A solved problem as the command line prints it: text, LaTeX or the JSON contract.

>>> from derive.problem import load
>>> result = solve(load("string_wrapped_disk"), {"m": "2", "M": "4", "R": "0.3"}, 6)
>>> result["answers"]["a"]["value"]
'-4.90500'
"""
from __future__ import annotations

import json

import sympy as sp

from derive import numeric, render, units
from derive.answers import Solution
from derive.mechanics.derivation import at_state
from derive.scene import DYNAMIC_KINDS
from derive.problem import Problem

_ROUTE_TITLES = {"lagrange": "Lagrange's method", "newton_euler": "Newton–Euler", "integration": "Integration"}


def route_title(route: str) -> str:
    """A heading for a route of derivation ("energy of the ball" stays as it is)."""
    return _ROUTE_TITLES.get(route, route[0].upper() + route[1:])


def _in_unit(value_si: sp.Expr, unit: str) -> sp.Expr:
    return value_si / units.si_factor(units.parse_unit(unit))


def answer_values(solution: Solution, values: dict[sp.Symbol, sp.Expr], digits: int,
                  names: list[str] | None = None) -> dict[str, str | None]:
    """Each answer's value (or those `names`) in its declared unit, to `digits` significant
    digits (the numbers of `derive solve`), after the problem's conditions are checked."""
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
            result[name] = numeric.evaluate(_in_unit(expression, ask.unit), values, digits)
        except (ValueError, ZeroDivisionError) as error:  # outside where the answer exists
            raise problem.error(f"ask.{name}", f"no real value at these parameters ({error})") from None
    return result


def solve(problem: Problem, overrides: dict[str, str] | None = None, digits: int = 15,
          solution: Solution | None = None) -> dict:
    """The JSON contract of `derive solve`: parameters, answers, equations of motion, checks.
    A Solution already derived for the problem may be passed in (it is the same derivation)."""
    solution = solution or Solution(problem)
    values = problem.values(overrides)
    parameters = {
        name: {
            "meaning": p.meaning,
            "unit": p.unit,
            "value": numeric.significant(_in_unit(values[p.symbol], p.unit), digits) if p.symbol in values else None,
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
            "latex": render.latex_of(expression),
            "unit": ask.unit,
            "value": numbers[name],
        }
    for name, ask in problem.asks.items():
        if ask.exact is not None:  # an approximation: its relative error at these parameters
            approximate, exact = answers[name]["value"], answers[ask.exact]["value"]
            error = None
            if approximate is not None and exact is not None and float(exact) != 0:
                ratio = numeric.evaluate(solution.expression(name) / solution.expression(ask.exact) - 1, values, 3)
                error = ratio
            answers[name]["approximation"] = {"exact": ask.exact, "relative_error": error}
    steps = solution.steps()
    kinds = {a.quantity.kind for a in problem.asks.values()}
    rest = solution.coordinates.at_rest_in_reference()
    equations = ({route: [sp.sstr(at_state(e, rest)) for e in d.at_rest_equations] for route, d in solution.derivations.items()}
                 if kinds & DYNAMIC_KINDS else {})
    checks = {c.name: {"passed": c.passed, "method": c.method, "detail": c.detail, "reading": c.reading}
              for c in solution.checks()}
    energy = ({k: sp.sstr(v) for k, v in solution.energy_ledger().items()} if kinds & DYNAMIC_KINDS else {})
    regimes = {}
    at_rest = {a.quantity.kind for a in problem.asks.values() if a.state is None}  # regimes are the placement's
    if at_rest & DYNAMIC_KINDS and solution.regimes[0].name:
        regimes = {"cases": [{"regime": r.name, "where": sp.sstr(w)}
                             for r, w in zip(solution.regimes, solution.regime_conditions())],
                   "applies": solution.regime_at(values)}
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
            route: [{"text": s.text, "latex": [render.latex_of(e) for e in s.equations]} for s in route_steps]
            for route, route_steps in steps.items()
        },
    }


def as_json(result: dict) -> str:
    return json.dumps(result, indent=2, ensure_ascii=False)


def as_text(result: dict) -> str:
    lines = [f"{result['title']}  ({result['id']}{', ' + result['source'] if result['source'] else ''})", ""]
    for route, equations in result["equations_of_motion"].items():
        lines.append(f"Equations of motion, {route_title(route)} (in the reference configuration, at rest):")
        lines += [f"  {e.replace('Eq(', '', 1)[:-1].replace(', ', ' = ', 1)}" for e in equations]
        lines.append("")
    lines.append("Answers:")
    width = max(len(n) for n in result["answers"])
    for name, a in result["answers"].items():
        unit = "" if a["unit"] in ("1", "") else f" {a['unit']}"
        value = f" = {a['value']}{unit}" if a["value"] is not None else f"  [{a['unit']}]"
        lines.append(f"  {name:<{width}} = {a['expr']}{value}")
        lines.append(f"  {'':<{width}}   ({a['meaning']})")
        if a.get("approximation") and a["approximation"]["relative_error"] is not None:
            lines.append(f"  {'':<{width}}   approximates {a['approximation']['exact']}: relative error "
                         f"{a['approximation']['relative_error']}")
    if result.get("regimes"):
        lines += ["", "Friction regimes (each where those above do not hold):"]
        lines += [f"  {c['regime']}: where {c['where']}" for c in result["regimes"]["cases"]]
        if result["regimes"]["applies"]:
            lines.append(f"  at these parameters the body {result['regimes']['applies']}")
    if result["energy"]:
        lines += ["", "Energy:"]
        lines += [f"  {k.replace('_', ' ')}: {v}" for k, v in result["energy"].items()]
    lines += ["", "Checks:"]
    for name, c in result["checks"].items():
        mark = "ok" if c["passed"] else "FAILED"
        lines.append(f"  [{mark}] {name} ({c['method']}): {c['detail']}")
    return "\n".join(lines)


def as_latex(result: dict) -> str:
    lines = [f"\\section*{{{result['title']}}}"]
    for route, steps in result["steps"].items():
        lines.append(f"\\subsection*{{{route_title(route)}}}")
        for step in steps:
            lines.append(f"{step['text']}:")
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
    return f"{render.symbol_latex(name)} = {answer['latex']}{value}"


def aligned(latex_equation: str) -> str:
    """Put the alignment point at the first '=' of a LaTeX equation."""
    return latex_equation.replace("=", "&=", 1)
