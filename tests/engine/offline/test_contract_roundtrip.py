"""One lossless contract: the plan re-made from the written causal.json alone is plan.json, byte for byte.

For every prompt-table row and every dev case, the offline agent animates the prompt; its causal.json
text is read back (the ``artimo`` block carries goals, what they are measured from, order, waits,
holds, returns and whole-object motion) and the planner and critic loop run from it alone.
"""

from __future__ import annotations

import json

import pytest

from app.engine.errors import GroundingError
from tests.conftest import REPO
from tests.engine.offline.conftest import animate, replan
from tests.engine.offline.test_prompt_table import ROWS

CASE_FILES = (("benchmark/cases/dev.jsonl", ""), ("benchmark/cases/dev_examples.jsonl", "examples/"))
PROMPTS = [(row.asset, row.prompt) for row in ROWS if not row.refuse] + [
    (prefix + json.loads(line)["asset"], json.loads(line)["prompt"])
    for name, prefix in CASE_FILES for line in (REPO / name).read_text().splitlines() if line.strip()
]


@pytest.mark.parametrize(("asset_name", "prompt"), PROMPTS, ids=[f"{a}: {p}" for a, p in PROMPTS])
def test_plan_from_written_causal_is_plan_json(asset_name: str, prompt: str) -> None:
    try:
        outcome = animate(asset_name, prompt)
    except GroundingError:
        pytest.skip("refused (the prompt table checks refusals)")
    written = outcome.causal.dumps()
    assert json.loads(written)["artimo"]["steps"], "causal.json carries the artimo block"
    assert replan(asset_name, written).dumps() == outcome.plan.dumps()


def test_prompts_cover_tables_and_dev_sets() -> None:
    assert len(PROMPTS) >= 300
