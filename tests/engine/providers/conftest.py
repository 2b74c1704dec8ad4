"""Run the pipeline against the local model server (tests/support/model_server.py)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from app.engine.config import EngineConfig
from app.engine.pipeline import PipelineRequest, PipelineResult, run_pipeline
from app.engine.providers.registry import ProviderConfig, make_roles
from tests.support.model_server import Script, model_server

PROMPT = "press the pedal to open the bin"
NO_RENDER = EngineConfig(render_images=False)


@dataclass
class Run:
    result: PipelineResult | None
    script: Script
    out: Path
    error: Exception | None = None

    @property
    def report(self) -> dict[str, Any]:
        return json.loads((self.out / "report.json").read_text())

    def calls(self, role: str) -> list[dict[str, Any]]:
        return [c for c in self.report["role_calls"] if c["role"] == role]


def run_model(
    examples_dir: Path, out: Path, replies: dict[str, list[Any]], *, provider: str = "openai", config: EngineConfig | None = None,
    models: tuple[tuple[str, str], ...] = (), profile: tuple[tuple[str, str], ...] = (), api_key: str = "test-key",
    asset: str = "pedal_bin", prompt: str = PROMPT, expect: type[Exception] | None = None, **server: Any,
) -> Run:
    """One pipeline run; with ``expect`` the run must raise that error (kept on the result)."""
    with model_server(replies, **server) as (url, script):
        base = url if provider == "openai" else url.removesuffix("/v1") + "/v1beta"
        roles = make_roles(provider, ProviderConfig(api_key=api_key, base_url=base, models=models, profile=profile), config or EngineConfig())
        try:
            result = run_pipeline(PipelineRequest(asset=examples_dir / asset, prompt=prompt), roles=roles, config=config, out_dir=out)
        except Exception as exc:
            if expect is None or not isinstance(exc, expect):
                raise
            return Run(None, script, out, exc)
        assert expect is None, f"expected {expect.__name__}"
        return Run(result, script, out)
