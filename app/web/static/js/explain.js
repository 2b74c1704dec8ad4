// "What happened": the causal chain (control -> effects), what the agent understood per
// clause and every warning, the critic rounds (keyframe images, issues, patches), timings,
// and every output as a download (signed links, so they open without a header).

import { api } from "./api.js";
import { bytes, errorBox, fill, genericTable, h, number, seconds, show } from "./dom.js";

const SHARE_CHOICES = [[3600, "1 hour"], [86400, "1 day"], [7 * 86400, "7 days"]];
const IMAGE_TYPES = new Set(["image/png", "image/jpeg", "image/gif"]);

function actionNode(action) {
  const role = action.target_role === "control" ? "control" : "direct";
  const links = action.target_links?.length ? action.target_links.join(", ") : action.target_link;
  return h("div", { class: `node ${role}`, dataset: { role: action.target_role } },
    h("b", {}, `${action.primitive} ${links}`),
    h("span", { class: "muted" }, action.target_role === "control" ? "control (operated by the user)" : "direct object (moved itself)"),
    action.magnitude !== null && action.magnitude !== undefined ? h("div", {}, `amount ${show(action.magnitude)}`) : null,
    action.control_return_behavior && action.control_return_behavior !== "unknown" ? h("div", {}, `then ${action.control_return_behavior}`) : null);
}

function effectsNode(effects) {
  if (!effects) return h("div", { class: "node" }, h("b", {}, "no effects"));
  return h("div", { class: "node" },
    h("b", {}, effects.effect_links?.length ? `moves ${effects.effect_links.join(", ")}` : "effects"),
    (effects.joint_targets || []).map((t) => h("div", {}, `${t.joint} → ${show(t.to)}`)),
    (effects.modes || []).map((m) => h("div", {}, `mode ${m.name} = ${m.set}`)),
    (effects.coupling_rules || []).map((rule) => h("div", { class: "muted" }, rule)));
}

function chainRow(title, action, effects) {
  return h("div", {},
    title ? h("div", { class: "muted" }, title) : null,
    h("div", { class: "chain" }, actionNode(action), h("span", { class: "arrow" }, "→"), effectsNode(effects)));
}

export function causalChain(causal) {
  if (!causal) return h("p", { class: "muted" }, "no causal.json in this job (a plan job skips the perceiver)");
  const rows = [];
  if (causal.causal?.has_causal && causal.causal.action) rows.push(chainRow(null, causal.causal.action, causal.causal.effects));
  for (const segment of causal.causal_segments || []) {
    rows.push(chainRow(`segment ${segment.segment_id} (order ${segment.time_hint?.order_index}${segment.time_hint?.overlap_ok ? ", may overlap" : ""})`,
      segment.action, segment.effects));
  }
  if (!rows.length) rows.push(h("p", { class: "muted" }, "no causal action: the prompt moves parts directly"));
  return h("div", { testid: "causal-chain" }, rows);
}

export function understanding(report) {
  const entries = report?.understanding;
  const body = Array.isArray(entries) && entries.length
    ? genericTable(entries, { testid: "understanding" })
    : h("p", { class: "muted", testid: "understanding" }, "no per-clause explanation in this report");
  const warnings = [...(report?.warnings || []).map((w) => ["warning", w]), ...(report?.events || []).map((e) => ["event", e])];
  return h("div", {}, body,
    h("h3", {}, `Warnings and executor events (${warnings.length})`),
    warnings.length
      ? h("div", { testid: "warnings" }, warnings.map(([kind, text]) => h("div", { class: kind === "warning" ? "warning" : "muted" }, text)))
      : h("p", { class: "muted", testid: "warnings" }, "none"));
}

function imagesOfRound(images, index) {
  const pattern = new RegExp(`(round|r)[_-]?0*${index}(\\D|$)`, "i");
  return images.filter((image) => pattern.test(image.name));
}

export function criticRounds(report, images, hrefOf) {
  const rounds = report?.critic_rounds || [];
  if (!rounds.length) return h("p", { class: "muted" }, "no critic rounds (plan job, or no critic)");
  const unassigned = images.filter((image) => !rounds.some((round) => imagesOfRound([image], round.index).length));
  return h("div", { class: "rounds", testid: "critic-rounds" },
    h("p", {}, `final: ${report.final_state || "–"}`),
    rounds.map((round) => h("div", { class: "round" },
      h("b", {}, `round ${round.index}`), " ", round.accepted ? "accepted" : "repaired",
      round.score !== null && round.score !== undefined ? ` · score ${number(round.score, 3)}` : "",
      h("div", {}, imagesOfRound(images, round.index).map((image) => h("img", { src: hrefOf(image.name), alt: image.name, title: image.name }))),
      h("h3", {}, `issues (${round.issues.length})`), genericTable(round.issues, { emptyText: "none" }),
      h("h3", {}, `patches (${round.patches.length})`), genericTable(round.patches, { emptyText: "none" }))),
    unassigned.length ? h("div", {}, h("h3", {}, "renders"), unassigned.map((image) => h("img", { src: hrefOf(image.name), alt: image.name, title: image.name, style: "max-width:220px" }))) : null);
}

export function timings(report, job) {
  const stages = report?.stages || [];
  const total = report?.total_s || job?.timings?.total;
  return h("div", { testid: "timings" },
    genericTable(stages.map((s) => ({ stage: s.stage, time: seconds(s.seconds) })), { emptyText: "no stage timings" }),
    h("p", {}, `total ${seconds(total)}`, report?.provider ? ` · provider ${report.provider}` : ""),
    report?.role_calls?.length ? h("div", {}, h("h3", {}, "role calls"), genericTable(report.role_calls.map((call) => ({
      role: call.role, provider: call.provider, model: call.model, attempts: call.attempts, time: seconds(call.seconds),
      tokens: `${call.usage?.input_tokens ?? 0} in / ${call.usage?.output_tokens ?? 0} out`, error: call.error,
    })))) : null);
}

/** The outputs as downloads through signed links (valid one day), with a share-link maker. */
export class ArtifactLinks {
  constructor(job) {
    this.job = job;
    this.links = new Map();
    this.expiry = h("select", {}, SHARE_CHOICES.map(([value, text]) => h("option", { value: String(value) }, text)));
    this.shareOut = h("div");
    this.element = h("div", { testid: "artifact-links" }, h("p", { class: "muted" }, "preparing links…"));
  }

  async load() {
    if (!this.job.artifacts.length) {
      fill(this.element, h("p", { class: "muted" }, "no outputs"));
      return this.links;
    }
    const answer = await api(`/v1/animations/${this.job.id}/links`, { method: "POST", json: { expires_in_s: 86400 } });
    for (const link of answer.links) this.links.set(link.name, link.url);
    fill(this.element,
      h("ul", { class: "artifacts" }, this.job.artifacts.map((artifact) => h("li", {},
        h("a", { href: this.links.get(artifact.name), download: artifact.name.split("/").pop(), dataset: { name: artifact.name } }, artifact.name),
        h("span", { class: "muted" }, ` ${bytes(artifact.size_bytes)} `),
        h("button", { class: "secondary", type: "button", onclick: () => this.share(artifact.name) }, "share link")))),
      h("div", { class: "row" }, h("span", { class: "muted" }, "share links expire after"), this.expiry),
      this.shareOut);
    return this.links;
  }

  async share(name) {
    try {
      const answer = await api(`/v1/animations/${this.job.id}/links`, { method: "POST", json: { names: [name], expires_in_s: Number(this.expiry.value) } });
      const url = answer.links[0].url;
      const input = h("input", { type: "text", value: url, readonly: true, style: "width: 100%", testid: "share-url" });
      fill(this.shareOut, h("p", {}, `${name}, valid until ${new Date(answer.expires_at).toLocaleString()}:`), input);
      input.select();
      navigator.clipboard?.writeText(url).catch(() => {});
    } catch (error) {
      fill(this.shareOut, errorBox(error.message));
    }
  }

  images() {
    return this.job.artifacts.filter((a) => IMAGE_TYPES.has(a.content_type) && a.name !== "preview.gif");
  }
}
