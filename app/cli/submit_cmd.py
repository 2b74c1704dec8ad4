"""``artimo submit ASSET --prompt ... --server URL``: run a job on an ArtiMo server."""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from app.cli.output import err, out, out_json

DEFAULT_SERVER = "http://127.0.0.1:8000"


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("submit", help="submit an asset + prompt to an ArtiMo server")
    parser.add_argument("asset", help="asset folder (zipped on the fly), .zip, or an uploaded asset's id/sha256")
    parser.add_argument("--prompt", required=True)
    parser.add_argument("--server", default=os.environ.get("ARTIMO_SERVER", DEFAULT_SERVER), help=f"default $ARTIMO_SERVER or {DEFAULT_SERVER}")
    parser.add_argument("--key", default=None, help="API key (default $ARTIMO_API_KEY)")
    parser.add_argument("--provider", default=None)
    parser.add_argument("--fps", type=int, choices=(24, 30), default=None)
    parser.add_argument("--critic-rounds", type=int, default=None, help="0..3")
    parser.add_argument("--preview", action="store_true", help="also render preview.gif (downloaded with --out)")
    parser.add_argument("--wait", action="store_true", help="wait until the job has finished")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds to wait (with --wait)")
    parser.add_argument("--out", type=Path, default=None, help="download the outputs here (implies --wait)")
    parser.set_defaults(handler=_submit)


def _submit(args: argparse.Namespace) -> int:
    from app.client import ArtimoClient, ClientError

    key = args.key or os.environ.get("ARTIMO_API_KEY")
    if not key:
        err("no API key: pass --key or set ARTIMO_API_KEY")
        return 2
    try:
        with ArtimoClient(args.server, key) as client:
            job = client.submit(args.asset, args.prompt, provider=args.provider, fps=args.fps, max_critic_rounds=args.critic_rounds,
                                preview=args.preview or None)
            err(f"job {job['id']} {job['status']}: {job['url']}")
            if not (args.wait or args.out):
                out(job["id"])
                return 0
            final = client.wait(job["id"], timeout=args.timeout)
            if args.out is not None:
                for path in client.download(job["id"], args.out):
                    err(f"wrote {path}")
    except ClientError as exc:
        err(f"error: {exc}")
        return 1
    out_json({k: final[k] for k in ("id", "status", "error", "error_kind", "timings")})
    return 0 if final["status"] == "succeeded" else 1
