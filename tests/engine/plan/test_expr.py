"""The safe ``q_target_expr`` language of SPEC §2 and ``velocity:<n>`` targets."""

from __future__ import annotations

import math

import pytest

from app.engine.errors import ExpressionError, PlanValidationError
from app.engine.plan.expr import MAX_EXPR_LENGTH, Limits, evaluate_expr, names_in, parse_expr, parse_velocity

DOOR = Limits(lower=-0.5, upper=2.0, rest=0.0)
SHIFTED = Limits(lower=0.2, upper=1.0, rest=0.2)
CONTINUOUS = Limits(lower=None, upper=None, rest=0.0)


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("upper_limit", 2.0),
        ("0.5*upper_limit", 1.0),
        ("-upper_limit", -2.0),
        ("lower_limit + 0.7*(upper_limit - lower_limit)", -0.5 + 0.7 * 2.5),
        ("deg(90)", math.pi / 2),
    ],
)
def test_spec_examples(text: str, value: float) -> None:
    assert evaluate_expr(text, DOOR) == pytest.approx(value, abs=1e-15)


@pytest.mark.parametrize(
    ("text", "value"),
    [
        ("1 + 2*3", 7.0),
        ("(1 + 2)*3", 9.0),
        ("8/4/2", 1.0),
        ("2 - 3 - 4", -5.0),
        ("1 - 2 + 3", 2.0),
        ("2*3/4", 1.5),
        ("-2*3", -6.0),
        ("2*-3", -6.0),
        ("--1", 1.0),
        ("-(1 + 2)", -3.0),
        ("+1.5", 1.5),
        ("- 2 * - 2", 4.0),
        ("1 - -1", 2.0),
        (".5 + 1e-1 + 2.5E1", 25.6),
        ("pi", math.pi),
        ("deg(180) - pi", 0.0),
        ("deg(45 + 45)", math.pi / 2),
        ("deg(-upper_limit)", math.radians(-2.0)),
        ("  upper_limit\t*\n0.5 ", 1.0),
        ("((((upper_limit))))", 2.0),
    ],
)
def test_arithmetic_precedence_and_unary_minus(text: str, value: float) -> None:
    assert evaluate_expr(text, DOOR) == pytest.approx(value, abs=1e-12)


def test_rest_stands_for_the_joint_rest_value() -> None:
    assert evaluate_expr("rest", SHIFTED) == 0.2
    assert evaluate_expr("rest + 0.5*(upper_limit - rest)", SHIFTED) == pytest.approx(0.6)
    assert evaluate_expr("rest", CONTINUOUS) == 0.0


def test_names_in() -> None:
    assert names_in(parse_expr("lower_limit + 0.7*(upper_limit - lower_limit) + deg(pi)")) == {
        "lower_limit",
        "upper_limit",
        "pi",
    }


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("", "empty"),
        ("   ", "empty"),
        ("upper", "unknown name 'upper'"),
        ("upper_limit * factor", "unknown name 'factor'"),
        ("__import__('os').system('true')", "unknown name '__import__'"),
        ("upper_limit.__class__", "unexpected '.'"),
        ("eval('1')", "unknown name 'eval'"),
        ("lambda: 1", "unknown name 'lambda'"),
        ("1 2", "unexpected '2'"),
        ("upper_limit)", "unexpected ')'"),
        ("upper_limit upper_limit", "unexpected 'upper_limit'"),
        ("1 +", "unexpected end"),
        ("1; 2", "unexpected ';'"),
        ("2**3", "unexpected '*'"),
        ("2^3", "unexpected '^'"),
        ("(1 + 2", "unexpected end"),
        ("deg 90", "expected '('"),
        ("deg(90", "unexpected end"),
        ("deg", "unexpected end"),
        ("1.2.3", "unexpected '.3'"),
        ("velocity:2", "unknown name 'velocity'"),
        ("[1]", "unexpected '['"),
    ],
)
def test_syntax_errors(text: str, says: str) -> None:
    with pytest.raises(ExpressionError) as caught:
        evaluate_expr(text, DOOR)
    assert says in str(caught.value)
    assert isinstance(caught.value, PlanValidationError)


def test_overlong_input() -> None:
    text = "1+" * (MAX_EXPR_LENGTH // 2) + "1"
    assert len(text) > MAX_EXPR_LENGTH
    with pytest.raises(ExpressionError, match="longer than"):
        parse_expr(text)
    assert evaluate_expr("1+" * ((MAX_EXPR_LENGTH - 1) // 2) + "1", DOOR) == (MAX_EXPR_LENGTH - 1) // 2 + 1


@pytest.mark.parametrize("text", ["1/0", "upper_limit/(upper_limit - upper_limit)", "1/(deg(0))"])
def test_division_by_zero(text: str) -> None:
    parse_expr(text)  # syntactically fine
    with pytest.raises(ExpressionError, match="divides by zero"):
        evaluate_expr(text, DOOR)


def test_non_finite_result() -> None:
    with pytest.raises(ExpressionError, match="not finite"):
        evaluate_expr("1e308*10", DOOR)


@pytest.mark.parametrize("text", ["upper_limit", "0.5*lower_limit", "rest + upper_limit"])
def test_a_limit_the_joint_lacks(text: str) -> None:
    with pytest.raises(ExpressionError, match="has no limits"):
        evaluate_expr(text, CONTINUOUS)


def test_numbers_and_pi_need_no_limits() -> None:
    assert evaluate_expr("2*pi + deg(90)", CONTINUOUS) == pytest.approx(2.5 * math.pi)


@pytest.mark.parametrize(
    ("text", "omega"),
    [
        ("velocity:2", 2.0),
        ("velocity:-1.5", -1.5),
        ("velocity: +3", 3.0),
        ("  velocity : 0.25 ", 0.25),
        ("velocity:1e1", 10.0),
        ("velocity:.5", 0.5),
        ("velocity:2radps", 2.0),
        ("velocity:-2_radps", -2.0),
    ],
)
def test_velocity_targets(text: str, omega: float) -> None:
    assert parse_velocity(text) == omega


@pytest.mark.parametrize(
    "text",
    [
        "velocity:fast",
        "velocity:unknown",
        "velocity:",
        "velocity:1e999",
        "velocity:inf",
        "upper_limit",
        "2",
        "velocity:2 rpm",
        "speed:2",
    ],
)
def test_not_velocity_targets(text: str) -> None:
    assert parse_velocity(text) is None
