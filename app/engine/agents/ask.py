"""``ask``: one role's question to a chat model, until the reply validates (bounded, recorded).

Each reply is read leniently (:mod:`replies`), validated against the role's pydantic
schema and an optional ``check`` against the asset/plan; problems go back to the model as
feedback. A reply cut at the output limit is asked again with twice the room (up to the
profile's cap). Every reply, valid or not, becomes a :class:`RoleCall` with its HTTP
attempts, tokens and estimated cost; when the role gives up, the calls travel on the
raised error so the report still lists them.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable, Sequence
from typing import TypeVar

from pydantic import BaseModel, ValidationError

from app.engine.agents.prompts import RenderedPrompt
from app.engine.agents.replies import NoJsonObject, parse_reply
from app.engine.errors import ExpressionError, PlanValidationError, ProviderError, ReplyTruncated, RoleOutputError
from app.engine.plan.checks import pydantic_issues
from app.engine.providers.base import ChatModel, Image, Message, ModelRequest, ModelResponse
from app.engine.report import RoleCall, TokenUsage, TransportAttempt

M = TypeVar("M", bound=BaseModel)
MAX_FEEDBACK_LINES = 20


class _Record:
    """Builds the RoleCall of each reply."""

    def __init__(self, model: ChatModel, prompt: RenderedPrompt) -> None:
        self.model = model
        self.prompt = prompt
        self.digest = hashlib.sha256((prompt.system + prompt.user).encode()).hexdigest()
        self.calls: list[RoleCall] = []

    def add(self, attempt: int, *, response: ModelResponse | None = None, error: str | None = None, usage: object = None,
            transport: Sequence[object] = (), finish: str | None = None) -> RoleCall:
        tokens = response.usage if response is not None else usage if isinstance(usage, TokenUsage) else TokenUsage()
        attempts = list(response.transport) if response is not None else [t for t in transport if isinstance(t, TransportAttempt)]
        call = RoleCall(role=self.prompt.role, provider=self.model.provider, model=response.model if response else self.model.model,
                        prompt_version=self.prompt.version, input_sha256=self.digest, attempts=attempt,
                        seconds=round(sum(a.seconds for a in attempts), 6), usage=tokens, error=None if error is None else error[:2000],
                        finish_reason=response.finish_reason if response else finish, output_mode=response.output_mode if response else None,
                        transport=attempts, est_cost_usd=self.model.profile.cost(tokens.input_tokens, tokens.output_tokens))
        self.calls.append(call)
        return call


def _problems(text: str, schema: type[M], check: Callable[[M], None] | None) -> tuple[M | None, list[str]]:
    try:
        value = parse_reply(text, schema)
        if check is not None:
            check(value)
        return value, []
    except NoJsonObject as exc:
        return None, [str(exc) + "; reply with one JSON object"]
    except ValidationError as exc:
        return None, pydantic_issues(exc)
    except PlanValidationError as exc:
        return None, exc.issues or [exc.message]
    except ExpressionError as exc:
        return None, [exc.message]


async def ask(
    model: ChatModel,
    prompt: RenderedPrompt,
    schema: type[M],
    *,
    attempts: int,
    images: Sequence[Image] = (),
    check: Callable[[M], None] | None = None,
) -> tuple[M, list[RoleCall]]:
    """Ask ``model`` until its reply validates against ``schema`` (and ``check``).

    Raises
    ------
    RoleOutputError
        No valid reply after ``attempts`` tries (the last problems are in the message).
    ProviderError
        The provider failed (after its own retries), refused or blocked the request.
    Both carry ``calls``: every RoleCall made.
    """
    messages: list[Message] = [Message(role="user", text=prompt.user, images=tuple(images))]
    record = _Record(model, prompt)
    limit = model.profile.max_output_tokens
    problems: list[str] = []
    for attempt in range(1, attempts + 1):
        request = ModelRequest(system=prompt.system, messages=tuple(messages), reply_model=schema, max_output_tokens=limit)
        try:
            response = await model.complete(request)
        except ReplyTruncated as exc:
            record.add(attempt, error=exc.message, usage=exc.usage, transport=exc.transport, finish="length")
            problems = [f"the reply was cut at the output limit of {exc.limit} tokens"]
            if limit >= model.profile.max_output_tokens_cap:
                problems.append(f"the cap is {model.profile.max_output_tokens_cap} tokens (raise max_output_tokens_cap in the model profile)")
                break
            limit = min(model.profile.max_output_tokens_cap, 2 * limit)
            continue
        except ProviderError as exc:
            record.add(attempt, error=exc.message, usage=exc.usage, transport=exc.transport)
            exc.calls = tuple(record.calls)
            raise
        value, problems = _problems(response.text, schema, check)
        if value is not None:
            record.add(attempt, response=response)
            return value, record.calls
        record.add(attempt, response=response, error="; ".join(problems))
        feedback = ("Your reply was not valid:\n" + "\n".join(f"- {p}" for p in problems[:MAX_FEEDBACK_LINES])
                    + "\nReply again with the corrected JSON object only.")
        messages += [Message(role="assistant", text=response.text), Message(role="user", text=feedback)]
    error = RoleOutputError(f"{prompt.role}: no valid reply after {len(record.calls)} attempts: " + "; ".join(problems[:5]), role=prompt.role)
    error.calls = tuple(record.calls)
    raise error
