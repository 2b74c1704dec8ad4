"""``artimo submit ASSET --prompt ... --server URL``: run a job on an ArtiMo server."""

from __future__ import annotations

import argparse
from pathlib import Path

from app.cli.output import err, out, out_json
from app.cli.server_options import add_server_options, model_options, open_client


def register(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("submit", help="submit an asset + prompt to an ArtiMo server")
    parser.add_argument("asset", help="asset folder (zipped on the fly), .zip, or an uploaded asset's id/sha256")
    parser.add_argument("--prompt", required=True)
    add_server_options(parser)
    parser.add_argument("--provider", default=None, help="offline (the server's default), openai or gemini (if the server has its key)")
    parser.add_argument("--model", action="append", default=[], metavar="ROLE=NAME",
                        help="model per role, e.g. --model planner=gpt-4.1 --model critic=geometric (repeatable)")
    parser.add_argument("--urdf", default=None, metavar="NAME", help="which URDF to use when the asset holds several")
    parser.add_argument("--fps", type=int, choices=(24, 30), default=None)
    parser.add_argument("--critic-rounds", type=int, default=None, help="0..3")
    parser.add_argument("--preview", action="store_true", help="also render preview.gif (downloaded with --out)")
    parser.add_argument("--wait", action="store_true", help="wait until the job has finished")
    parser.add_argument("--timeout", type=float, default=900.0, help="seconds to wait (with --wait)")
    parser.add_argument("--out", type=Path, default=None, help="download the outputs here (implies --wait)")
    parser.set_defaults(handler=_submit)


def _submit(args: argparse.Namespace) -> int:
    from app.client import ClientError

    try:
        models = model_options(args.model)
    except ValueError as exc:
        err(f"error: {exc}")
        return 2
    client = open_client(args)
    if client is None:
        return 2
    try:
        with client:
            problem = _local_asset_problem(args.asset, args.urdf)
            if problem is not None:  # before zipping and uploading a folder the server would refuse
                err(f"error: {problem}")
                return 1
            job = client.submit(args.asset, args.prompt, provider=args.provider, fps=args.fps, max_critic_rounds=args.critic_rounds,
                                preview=args.preview or None, urdf=args.urdf, **models)
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


def _local_asset_problem(asset: str, urdf: str | None) -> str | None:
    """The server's refusal of a local folder or zip for its URDFs (several and no ``--urdf``, none, or an
    ``--urdf`` matching none), found from the file names alone; None when it has one to use, or is not local."""
    import zipfile

    from app.engine.asset.urdf_choice import find_urdf, urdf_in_zip
    from app.engine.errors import AssetError

    path = Path(asset)
    try:
        if path.is_dir():
            find_urdf(path.resolve(), requested=urdf)
        elif path.is_file() and zipfile.is_zipfile(path):
            urdf_in_zip(path, urdf)
    except AssetError as exc:
        return str(exc)
    return None
