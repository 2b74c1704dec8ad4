// Calls to the ArtiMo API with the key kept in this browser, and a job's live progress
// (server-sent events read with fetch, so the key travels in a header; polling when the
// stream cannot be used).

const KEY_STORAGE = "artimo.apiKey";
const POLL_MS = 1000;
const TERMINAL = new Set(["succeeded", "failed", "cancelled"]);

export class ApiError extends Error {
  constructor(status, body) {
    super(describe(status, body));
    this.status = status;
    this.body = body;
  }
}

function describe(status, body) {
  if (body && typeof body.detail === "string") return `${status}: ${body.detail}`;
  if (body && Array.isArray(body.detail)) {
    return `${status}: ` + body.detail.map((e) => `${(e.loc || []).join(".")}: ${e.msg}`).join("; ");
  }
  return `HTTP ${status}`;
}

export function getKey() {
  return localStorage.getItem(KEY_STORAGE) || "";
}

export function setKey(key) {
  if (key) localStorage.setItem(KEY_STORAGE, key.trim());
  else localStorage.removeItem(KEY_STORAGE);
}

/** Take a sign-in token from the address (#login=...), keep it, and remove it from the address bar. */
export function adoptLoginFromLocation() {
  const match = /(?:^#|&)login=([^&]+)/.exec(location.hash);
  if (!match) return false;
  setKey("artimo-page." + decodeURIComponent(match[1]).replace(/^artimo-page\./, ""));
  history.replaceState(null, "", location.pathname + location.search + "#/jobs");
  return true;
}

function headers(extra) {
  const result = { ...extra };
  const key = getKey();
  if (key) result.Authorization = `Bearer ${key}`;
  return result;
}

async function parse(response) {
  const type = response.headers.get("content-type") || "";
  if (type.includes("json")) return response.json();
  return response.text();
}

/** JSON (or text) from an API path; throws ApiError with the server's detail. */
export async function api(path, { method = "GET", body, json, signal } = {}) {
  const init = { method, headers: headers(), signal };
  if (json !== undefined) {
    init.body = JSON.stringify(json);
    init.headers["Content-Type"] = "application/json";
  } else if (body !== undefined) {
    init.body = body;
  }
  const response = await fetch(path, init);
  const data = await parse(response);
  if (!response.ok) throw new ApiError(response.status, data);
  return data;
}

/** Raw bytes of an output (the key goes in the header, so no signed link is needed here). */
export async function apiBytes(path) {
  const response = await fetch(path, { headers: headers() });
  if (!response.ok) throw new ApiError(response.status, await parse(response));
  return response.arrayBuffer();
}

/** Text of an output, or null when the job has no such file (404). */
export async function apiTextOrNull(path) {
  const response = await fetch(path, { headers: headers() });
  if (response.status === 404) return null;
  if (!response.ok) throw new ApiError(response.status, await parse(response));
  return response.text();
}

function parseEvents(buffer, onEvent) {
  const blocks = buffer.split("\n\n");
  const rest = blocks.pop();
  for (const block of blocks) {
    let name = "message";
    const data = [];
    for (const line of block.split("\n")) {
      if (line.startsWith("event:")) name = line.slice(6).trim();
      else if (line.startsWith("data:")) data.push(line.slice(5).trim());
    }
    if (data.length) onEvent(name, JSON.parse(data.join("\n")));
  }
  return rest;
}

async function streamOnce(id, onUpdate, controller) {
  const response = await fetch(`/v1/animations/${id}/events`, {
    headers: headers({ Accept: "text/event-stream" }), signal: controller.signal,
  });
  if (!response.ok || !response.body) throw new ApiError(response.status, await parse(response));
  const reader = response.body.pipeThrough(new TextDecoderStream()).getReader();
  let buffer = "";
  let finished = false;
  for (;;) {
    const { value, done } = await reader.read();
    if (done) break;
    buffer = parseEvents(buffer + value, (name, data) => {
      if (name === "job") onUpdate(data, "events");
      if (name === "end") finished = true;
    });
  }
  return finished;
}

async function poll(id, onUpdate, controller) {
  while (!controller.signal.aborted) {
    const job = await api(`/v1/animations/${id}`, { signal: controller.signal });
    onUpdate(job, "polling");
    if (TERMINAL.has(job.status)) return;
    await new Promise((resolve) => setTimeout(resolve, POLL_MS));
  }
}

/**
 * Follow a job until it finishes: server-sent events first (reconnecting when the server
 * closes a stream early), polling when the stream fails. Returns a function that stops it.
 * onUpdate(state, how) gets each new state; how is "events" or "polling".
 */
export function watchJob(id, onUpdate, { events = true } = {}) {
  const controller = new AbortController();
  (async () => {
    let streamed = events && "TextDecoderStream" in window;
    while (streamed && !controller.signal.aborted) {
      try {
        if (await streamOnce(id, onUpdate, controller)) return;
      } catch (error) {
        if (controller.signal.aborted) return;
        console.warn("event stream failed, polling instead:", error.message);
        streamed = false;
      }
    }
    if (!controller.signal.aborted) await poll(id, onUpdate, controller).catch((e) => {
      if (!controller.signal.aborted) onUpdate({ id, status: "unknown", error: e.message }, "polling");
    });
  })();
  return () => controller.abort();
}

export function isTerminal(status) {
  return TERMINAL.has(status);
}
