"""Every prompt template renders with a sample context; a missing variable is an error."""

from __future__ import annotations

import pytest

from app.engine.agents.prompts import PromptError, PromptStore
from app.engine.config import EngineConfig

SAMPLES = {
    "perceiver": {"prompt": "open the door", "links": [{"name": "door", "label": "door", "joint": "hinge", "joint_type": "revolute"}],
                  "joint_summary": "{}", "scale_context": "{}", "images": ["overlay_view_01.png"]},
    "planner": {"prompt": "open the door", "joint_summary": "{}", "scale_context": "{}", "causal": "{}"},
    "critic": {"prompt": "open the door", "segment_index": 0, "phase_type": "effect_motion", "joint": "hinge", "link": "door",
               "intended": "move to 1.57", "summary": "{}", "images": []},
}


@pytest.mark.parametrize("role", sorted(SAMPLES))
def test_template_renders(role: str) -> None:
    rendered = PromptStore(EngineConfig().prompts_dir).render(role, **SAMPLES[role])
    assert rendered.version.startswith(role) and len(rendered.sha256) == 64
    assert "open the door" in rendered.user and role in rendered.system.lower()
    assert "{{" not in rendered.user


@pytest.mark.parametrize("role", sorted(SAMPLES))
def test_missing_variable_fails(role: str) -> None:
    variables = dict(SAMPLES[role])
    variables.pop("prompt")
    with pytest.raises(PromptError):
        PromptStore(EngineConfig().prompts_dir).render(role, **variables)


def test_unknown_template(tmp_path) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(PromptError):
        PromptStore(tmp_path).render("perceiver", **SAMPLES["perceiver"])
