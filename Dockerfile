# syntax=docker/dockerfile:1.7
# ArtiMo service image: one image for the API, the Celery workers and the migration job.
# The command is chosen per service in docker-compose.yml (default: the API).
#   docker build -t artimo .
#   docker run --rm -e ARTIMO_API_KEY=... -p 8000:8000 artimo          # API (embedded SQLite unless DATABASE_URL/REDIS_URL)
#   docker run --rm artimo celery -A workers.celery_app worker         # a worker
# Front-end packages of the page and the API docs (three.js, Swagger UI, Redoc) from the npm
# registry, with Debian's Node.js; only the installed folder goes into the image.
FROM python:3.11-slim AS web
RUN apt-get update && apt-get install -y --no-install-recommends nodejs npm && rm -rf /var/lib/apt/lists/*
WORKDIR /web
COPY app/web/package.json app/web/package-lock.json app/web/.npmrc ./
RUN npm ci --no-audit --no-fund --ignore-scripts --legacy-peer-deps

FROM python:3.11-slim

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1 \
    PYOPENGL_PLATFORM=egl \
    ARTIMO_DATA_DIR=/data

# Mesa EGL: offscreen rendering for render-enabled jobs (CPU, llvmpipe)
RUN apt-get update \
 && apt-get install -y --no-install-recommends libegl1 libegl-mesa0 libgl1-mesa-dri libgomp1 \
 && rm -rf /var/lib/apt/lists/*

RUN useradd --create-home --uid 10001 artimo && mkdir -p /data && chown artimo /data
WORKDIR /app

# Layer 1: third-party dependencies only, rebuilt when pyproject.toml changes.
ARG EXTRAS=service,models,render,usd,mjcf
COPY pyproject.toml ./
RUN python - <<'PY' > /tmp/requirements.txt && pip install -r /tmp/requirements.txt && rm /tmp/requirements.txt
import os, tomllib
project = tomllib.load(open("pyproject.toml", "rb"))["project"]
requirements = list(project["dependencies"])
for extra in os.environ.get("EXTRAS", "").split(","):
    requirements += project["optional-dependencies"].get(extra.strip(), [])
print("\n".join(sorted(set(requirements))))
PY

# Layer 2: the project itself (app, workers, benchmark, prompts/, migrations/), no dependency resolution.
COPY README.md ./
COPY app ./app
COPY workers ./workers
COPY benchmark ./benchmark
COPY prompts ./prompts
COPY migrations ./migrations
COPY --from=web /web/node_modules ./app/web/node_modules
RUN pip install --no-deps -e . && python -c "import app.engine, workers.broker"

USER artimo
VOLUME ["/data"]
EXPOSE 8000
CMD ["uvicorn", "app.main:create_app", "--factory", "--host", "0.0.0.0", "--port", "8000", "--proxy-headers", "--forwarded-allow-ips", "*"]
