// Batches: their cases with status; for a benchmark batch (POST /v1/benchmarks) the
// per-case scores and, per case, the ground-truth key states against the matched
// predicted frames.

import { ApiError, api } from "./api.js";
import { errorBox, fill, h, number, statusBadge, when } from "./dom.js";

const METRICS = ["P_gIoU", "P_PC", "P_OccF1"];

export async function showBatchList(root) {
  fill(root, h("section", { class: "panel" }, h("h2", {}, "Batches"), h("p", { class: "muted" }, "loading…")));
  let batches;
  try {
    batches = (await api("/v1/batches?limit=100")).data;
  } catch (error) {
    fill(root, h("section", { class: "panel" }, h("h2", {}, "Batches"), errorBox(error.message)));
    return;
  }
  fill(root, h("section", { class: "panel", testid: "batches" }, h("h2", {}, "Batches"),
    batches.length ? h("table", { class: "grid" },
      h("thead", {}, h("tr", {}, h("th", {}, "name"), h("th", {}, "cases"), h("th", {}, "created"))),
      h("tbody", {}, batches.map((batch) => h("tr", {},
        h("td", {}, h("a", { href: `#/batches/${batch.id}` }, batch.name || batch.id.slice(0, 8))),
        h("td", {}, String(batch.count)), h("td", {}, when(batch.created_at))))))
      : h("p", { class: "muted" }, "no batches yet (POST /v1/batches, or POST /v1/benchmarks for scored cases)")));
}

function keyStates(result) {
  return h("table", { class: "grid" },
    h("thead", {}, h("tr", {}, ["state", "phase", "GT time", "pred time", ...METRICS, "GT joints", "predicted joints"].map((t) => h("th", {}, t)))),
    h("tbody", {}, result.states.map((state) => h("tr", {},
      h("td", {}, String(state.index)), h("td", {}, state.phase),
      h("td", {}, `${number(state.gt_time_s, 2)} s`), h("td", {}, state.pred_time_s === null ? "–" : `${number(state.pred_time_s, 2)} s`),
      METRICS.map((m) => h("td", {}, number(state.values[m], 3))),
      h("td", {}, Object.entries(state.gt_joints || {}).map(([j, v]) => h("div", {}, `${j} ${number(v, 3)}`))),
      h("td", {}, Object.entries(state.pred_joints || {}).map(([j, v]) => h("div", {}, `${j} ${number(v, 3)}`)))))));
}

export async function showBatch(root, id) {
  fill(root, h("section", { class: "panel" }, h("h2", {}, "Batch"), h("p", { class: "muted" }, "loading…")));
  const batch = await api(`/v1/batches/${id}`);
  let scores = null;
  try {
    scores = await api(`/v1/batches/${id}/scores`);
  } catch (error) {
    if (!(error instanceof ApiError && error.status === 404)) throw error;
  }
  const byCase = new Map((scores?.cases || []).map((c) => [c.case_id, c]));
  const detail = h("div");
  const counts = Object.entries(batch.status_counts).filter(([, n]) => n).map(([s, n]) => `${n} ${s}`).join(", ");
  fill(root, h("section", { class: "panel", testid: "batch" },
    h("h2", {}, batch.name || `batch ${batch.id.slice(0, 8)}`),
    h("p", {}, `${batch.count} cases: ${counts}${batch.done ? "" : " (running)"}`),
    scores ? h("p", { testid: "batch-scores" }, "mean ", METRICS.map((m) => `${m} ${number(scores.summary[m], 3)}  `),
      `over ${scores.summary.scored} scored of ${scores.cases.length} cases`) : h("p", { class: "muted" }, "not a benchmark batch: no scores"),
    h("table", { class: "grid" },
      h("thead", {}, h("tr", {}, ["case", "status", ...(scores ? METRICS : []), "job"].map((t) => h("th", {}, t)))),
      h("tbody", {}, batch.cases.map((item) => {
        const result = byCase.get(item.case_id);
        return h("tr", { dataset: { case: item.case_id || "" } },
          h("td", {}, result?.states?.length
            ? h("a", { href: "#", onclick: (event) => { event.preventDefault(); fill(detail, h("h3", {}, `key states of ${item.case_id}`), keyStates(result)); } }, item.case_id)
            : item.case_id || "–"),
          h("td", {}, statusBadge(item.status), item.error ? h("div", { class: "muted" }, item.error.slice(0, 160)) : null),
          scores ? METRICS.map((m) => h("td", {}, result?.values ? number(result.values[m], 3) : (result?.note || "–"))) : null,
          h("td", {}, h("a", { href: `#/jobs/${item.job_id}` }, "open")));
      }))),
    detail));
}
