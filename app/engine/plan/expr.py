"""The safe ``q_target_expr`` language (SPEC §2). Never ``eval``.

Grammar::

    expr   := term (("+" | "-") term)*
    term   := unary (("*" | "/") unary)*
    unary  := "-" unary | "+" unary | atom
    atom   := NUMBER | "pi" | "upper_limit" | "lower_limit" | "rest"
            | "deg" "(" expr ")" | "(" expr ")"

Examples: ``upper_limit``, ``0.5*upper_limit``, ``-upper_limit``,
``lower_limit + 0.7*(upper_limit - lower_limit)``, ``deg(90)``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache

from app.engine.errors import ExpressionError

MAX_EXPR_LENGTH = 200
_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)|([A-Za-z_][A-Za-z_0-9]*)|(.))")
NAMES = frozenset({"pi", "upper_limit", "lower_limit", "rest"})
_VELOCITY = re.compile(r"^\s*velocity\s*:\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(?:_?radps)?\s*$")


@dataclass(frozen=True)
class Node:
    op: str
    value: float = 0.0
    name: str = ""
    args: tuple[Node, ...] = ()


@dataclass(frozen=True)
class Limits:
    """Values the names of an expression stand for; ``None`` = the joint has no such limit."""

    lower: float | None
    upper: float | None
    rest: float = 0.0


def _tokens(text: str) -> list[tuple[str, str]]:
    out = []
    position = 0
    while position < len(text):
        match = _TOKEN.match(text, position)
        if match is None or match.end() == position:
            break
        number, name, other = match.groups()
        position = match.end()
        if number is not None:
            out.append(("num", number))
        elif name is not None:
            out.append(("name", name))
        elif other is not None and other.strip():
            out.append(("op", other))
    return out


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.tokens = _tokens(text)
        self.index = 0

    def fail(self, why: str) -> ExpressionError:
        return ExpressionError(f"invalid target expression {self.text!r}: {why}")

    def peek(self) -> tuple[str, str] | None:
        return self.tokens[self.index] if self.index < len(self.tokens) else None

    def take(self) -> tuple[str, str]:
        token = self.peek()
        if token is None:
            raise self.fail("unexpected end")
        self.index += 1
        return token

    def expect(self, value: str) -> None:
        token = self.take()
        if token != ("op", value):
            raise self.fail(f"expected '{value}', found '{token[1]}'")

    def parse(self) -> Node:
        node = self.expr()
        if self.peek() is not None:
            raise self.fail(f"unexpected '{self.peek()[1]}'")  # type: ignore[index]
        return node

    def expr(self) -> Node:
        node = self.term()
        while self.peek() in (("op", "+"), ("op", "-")):
            op = self.take()[1]
            node = Node(op=op, args=(node, self.term()))
        return node

    def term(self) -> Node:
        node = self.unary()
        while self.peek() in (("op", "*"), ("op", "/")):
            op = self.take()[1]
            node = Node(op=op, args=(node, self.unary()))
        return node

    def unary(self) -> Node:
        if self.peek() in (("op", "-"), ("op", "+")):
            op = self.take()[1]
            inner = self.unary()
            return Node(op="neg", args=(inner,)) if op == "-" else inner
        return self.atom()

    def atom(self) -> Node:
        kind, value = self.take()
        if kind == "num":
            return Node(op="num", value=float(value))
        if kind == "name":
            if value == "deg":
                self.expect("(")
                inner = self.expr()
                self.expect(")")
                return Node(op="deg", args=(inner,))
            if value not in NAMES:
                raise self.fail(f"unknown name '{value}' (allowed: {', '.join(sorted(NAMES | {'deg'}))})")
            return Node(op="name", name=value)
        if value == "(":
            inner = self.expr()
            self.expect(")")
            return inner
        raise self.fail(f"unexpected '{value}'")


@lru_cache(maxsize=1024)
def parse_expr(text: str) -> Node:
    """Parse ``text``.

    Raises
    ------
    ExpressionError
        Empty, too long, or not in the grammar.
    """
    if not isinstance(text, str) or not text.strip():
        raise ExpressionError(f"invalid target expression {text!r}: empty")
    if len(text) > MAX_EXPR_LENGTH:
        raise ExpressionError(f"invalid target expression: longer than {MAX_EXPR_LENGTH} characters")
    return _Parser(text).parse()


def names_in(node: Node) -> set[str]:
    found = {node.name} if node.op == "name" else set()
    for arg in node.args:
        found |= names_in(arg)
    return found


def evaluate(node: Node, limits: Limits, text: str = "") -> float:
    """Value of a parsed expression.

    Raises
    ------
    ExpressionError
        A limit the joint lacks, division by zero, or a non-finite result.
    """
    if node.op == "num":
        return node.value
    if node.op == "name":
        if node.name == "pi":
            return math.pi
        if node.name == "rest":
            return limits.rest
        value = limits.upper if node.name == "upper_limit" else limits.lower
        if value is None:
            raise ExpressionError(f"target expression {text!r} uses {node.name}, but the joint has no limits")
        return value
    values = [evaluate(arg, limits, text) for arg in node.args]
    if node.op == "neg":
        result = -values[0]
    elif node.op == "deg":
        result = math.radians(values[0])
    elif node.op == "+":
        result = values[0] + values[1]
    elif node.op == "-":
        result = values[0] - values[1]
    elif node.op == "*":
        result = values[0] * values[1]
    else:
        if values[1] == 0.0:
            raise ExpressionError(f"target expression {text!r} divides by zero")
        result = values[0] / values[1]
    if not math.isfinite(result):
        raise ExpressionError(f"target expression {text!r} is not finite")
    return result


def evaluate_expr(text: str, limits: Limits) -> float:
    """Parse and evaluate ``text`` against ``limits``."""
    return evaluate(parse_expr(text), limits, text)


def parse_velocity(text: str) -> float | None:
    """The number of a ``velocity:<number>`` target (``radps`` suffix allowed), else ``None``."""
    match = _VELOCITY.match(text) if isinstance(text, str) else None
    if match is None:
        return None
    value = float(match.group(1))
    return value if math.isfinite(value) else None
