// One job: live progress while it runs; once finished, the player with its scrubber, phase
// timeline, joint curves and joint panel, "what happened", and the plan editor.

import { api, apiBytes, apiTextOrNull, isTerminal, watchJob } from "./api.js";
import { errorBox, fill, h, number, statusBadge, when } from "./dom.js";
import { ArtifactLinks, causalChain, criticRounds, timings, understanding } from "./explain.js";
import { PlanEditor } from "./plan_editor.js";
import { JointCurves, PhaseTimeline } from "./timeline.js";

const STAGES = ["load_asset", "preprocess", "perceive", "plan", "refine", "export", "preview", "report"];
const PLAN_STAGES = ["execute", "report"];
const SPEEDS = [0.25, 0.5, 1, 2];

function parseTrajectory(text) {
  return text.split("\n").filter((line) => line.trim()).map((line) => JSON.parse(line));
}

export class JobView {
  constructor(root, id, { onSubmitted, onChanged }) {
    this.root = root;
    this.id = id;
    this.onSubmitted = onSubmitted;
    this.onChanged = onChanged;
    this.status = h("span", { testid: "job-status" });
    this.progress = h("div");
    this.body = h("div", { class: "job-body" });
    this.header = h("section", { class: "panel" }, h("h2", { id: "job-title" }, "Job"), this.status, this.progress);
    delete root.dataset.loaded;
    fill(root, this.header, this.body);
  }

  async open() {
    this.job = await api(`/v1/animations/${this.id}`);
    api(`/v1/assets/${this.job.asset_id}`).then((asset) => { this.assetName = asset.filename; }).catch(() => {});
    fill(this.header.querySelector("#job-title"), this.job.prompt);
    this.showState(this.job, "request");
    if (isTerminal(this.job.status)) return this.showResults();
    let last = this.job.status;
    this.stop = watchJob(this.id, (state, how) => {
      this.showState(state, how);
      if (state.status !== last) { last = state.status; this.onChanged?.(); }
      if (isTerminal(state.status)) {
        this.stop?.();
        api(`/v1/animations/${this.id}`).then((job) => { this.job = job; this.showResults(); });
      }
    });
  }

  showState(state, how) {
    this.how = how;
    const ran = this.report?.stages?.map((s) => s.stage);
    const stages = ran?.length ? ran : (this.job.options?.plan_sha256 ? PLAN_STAGES : STAGES);
    const current = stages.indexOf(state.stage);
    const detail = state.status === "running" ? `${state.stage || "starting"} ${state.progress ?? 0}%` : (state.stage || "");
    this.root.dataset.status = state.status;
    fill(this.status, statusBadge(state.status), " ", h("span", { class: "muted" }, `${detail} (${how}) · `), state.status);
    fill(this.progress,
      h("div", { class: "stages" }, stages.map((stage, index) => h("span", {
        class: `stage ${index < current || state.status === "succeeded" ? "done" : ""} ${index === current && state.status === "running" ? "current" : ""}`,
      }, stage))),
      state.status === "running" || state.status === "queued" ? h("progress", { max: 100, value: state.progress ?? 0 }) : null,
      state.error ? errorBox(`${state.error_kind || "error"}: ${state.error}`) : null,
      h("p", { class: "muted" }, `asset ${this.assetName || this.job.asset_id.slice(0, 8)} · created ${when(this.job.created_at)}`,
        this.job.options?.plan_sha256 ? " · plan job (executor + exporters only)" : "",
        !isTerminal(state.status) ? h("button", { class: "secondary", type: "button", style: "margin-left: 8px",
          onclick: () => api(`/v1/animations/${this.id}`, { method: "DELETE" }).catch(() => {}) }, "cancel") : null));
  }

  async showResults() {
    const names = new Set(this.job.artifacts.map((a) => a.name));
    const base = `/v1/animations/${this.id}`;
    const [reportText, planText, causalText, trajectoryText] = await Promise.all(
      ["report.json", "plan.json", "causal.json", "trajectory.jsonl"].map((name) => (names.has(name) ? apiTextOrNull(`${base}/${name}`) : null)));
    this.report = reportText ? JSON.parse(reportText) : null;
    this.plan = planText ? JSON.parse(planText) : null;
    this.causal = causalText ? JSON.parse(causalText) : null;
    this.frames = trajectoryText ? parseTrajectory(trajectoryText) : [];
    this.showState(this.job, this.how || "request"); // the stages this run went through
    this.artifacts = new ArtifactLinks(this.job);
    const explain = h("section", { class: "panel", testid: "explain" }, h("h2", {}, "What happened"));
    const sections = [];
    if (names.has("animation.glb")) sections.push(await this.playerSection());
    sections.push(explain);
    fill(this.body, sections);
    const links = await this.artifacts.load().catch((error) => { fill(this.artifacts.element, errorBox(error.message)); return new Map(); });
    const hrefOf = (name) => links.get(name) || "";
    explain.append(
      h("h3", {}, "Causal chain"), causalChain(this.causal),
      h("h3", {}, "What the agent understood, per clause"), understanding(this.report),
      h("h3", {}, "Critic rounds"), criticRounds(this.report, this.artifacts.images(), hrefOf),
      h("h3", {}, "Timings"), timings(this.report, this.job),
      h("h3", {}, "Outputs"), this.artifacts.element);
    if (this.plan && this.job.status === "succeeded") {
      const editor = new PlanEditor(this.job, this.plan, this.joints || [], { onSubmitted: this.onSubmitted });
      this.body.append(h("section", { class: "panel" }, h("h2", {}, "Correct it"), editor.element));
    }
    this.root.dataset.loaded = "true";
  }

  async playerSection() {
    const { Player } = await import("./player.js"); // three.js loads only when there is something to show
    this.timeline = new PhaseTimeline({ onSeek: (t) => { this.player.pause(); this.player.setTime(t); } });
    this.curves = new JointCurves();
    this.scrubber = h("input", { type: "range", class: "range-styled", testid: "scrubber", min: 0, max: 1, step: "any", value: 0,
      oninput: () => { this.player.pause(); this.syncPlay(); this.player.setTime(Number(this.scrubber.value)); } });
    this.playButton = h("button", { type: "button", testid: "play", onclick: () => this.togglePlay() }, "▶ Play");
    this.speed = h("select", { testid: "speed", onchange: () => { this.player.speed = Number(this.speed.value); } },
      SPEEDS.map((s) => h("option", { value: String(s), selected: s === 1 }, `${s}×`)));
    this.clockText = h("span", { class: "muted", testid: "time" });
    this.jointPanel = h("div", { testid: "joint-panel" });
    this.player = new Player({ onTime: (t) => this.onTime(t) });
    window.artimoPlayer = this.player; // for the browser tests and the console
    const section = h("section", { class: "panel" }, h("h2", {}, "Animation"),
      h("div", { class: "player-grid" },
        h("div", {}, this.player.element,
          h("div", { class: "controls" }, this.playButton, this.speed, this.clockText, h("span", { class: "muted" }, "drag to orbit, wheel to zoom")),
          h("div", { class: "scrubber-row" }, this.scrubber),
          this.timeline.element, this.curves.element),
        h("div", {}, h("h3", {}, "Joints"), this.jointPanel)));
    fill(this.body, section);
    const loaded = await this.player.load(await apiBytes(`/v1/animations/${this.id}/animation.glb`));
    this.joints = loaded.joints;
    const lastFrame = this.frames[this.frames.length - 1];
    this.duration = Math.max(loaded.duration, lastFrame?.time_s || 0);
    this.scrubber.max = String(this.duration);
    this.timeline.show(this.plan, this.duration);
    this.curves.show(this.frames, this.joints, this.duration);
    this.onTime(0);
    return section;
  }

  togglePlay() {
    if (this.player.playing) this.player.pause(); else this.player.play();
    this.syncPlay();
  }

  syncPlay() {
    this.playButton.textContent = this.player.playing ? "❚❚ Pause" : "▶ Play";
    this.playButton.dataset.playing = String(this.player.playing);
  }

  frameAt(t) {
    if (!this.frames.length) return null;
    const step = this.frames.length > 1 ? this.frames[1].time_s - this.frames[0].time_s : 1;
    const index = Math.min(Math.max(Math.round(t / step), 0), this.frames.length - 1);
    return this.frames[index];
  }

  onTime(t) {
    if (!this.scrubber) return;
    if (document.activeElement !== this.scrubber) this.scrubber.value = String(t);
    this.scrubber.dataset.time = t.toFixed(4);
    this.timeline.setTime(t);
    this.curves.setTime(t);
    const frame = this.frameAt(t);
    this.clockText.textContent = `${t.toFixed(2)} / ${(this.duration || 0).toFixed(2)} s${frame ? ` · frame ${frame.frame_idx}` : ""}`;
    this.drawJoints(frame);
  }

  drawJoints(frame) {
    if (!frame || !this.joints) return;
    this.jointPanel.dataset.frame = String(frame.frame_idx);
    fill(this.jointPanel, h("table", { class: "grid" },
      h("thead", {}, h("tr", {}, h("th", {}, "joint"), h("th", {}, "value"), h("th", {}, "limits"))),
      h("tbody", {}, this.joints.map((joint) => {
        const value = frame.joint_angles[joint.name];
        const unit = joint.type === "prismatic" ? "m" : "rad";
        const bounded = joint.lower !== null && joint.upper !== null && joint.upper > joint.lower;
        const fraction = bounded ? (value - joint.lower) / (joint.upper - joint.lower) : null;
        return h("tr", { dataset: { joint: joint.name, value: String(value) } },
          h("td", { title: `${joint.type}, link ${joint.link}` }, joint.name),
          h("td", {}, `${number(value, 3)} ${unit}`, unit === "rad" ? h("div", { class: "muted" }, `${number((value * 180) / Math.PI, 1)}°`) : null),
          h("td", {}, bounded ? `[${number(joint.lower, 2)}, ${number(joint.upper, 2)}]` : "free",
            bounded ? h("div", { class: "joint-bar" }, h("i", { style: `left: calc(${Math.min(Math.max(fraction, 0), 1) * 100}% - 1px)` })) : null));
      }))));
  }

  close() {
    this.stop?.();
    this.player?.dispose();
  }
}
