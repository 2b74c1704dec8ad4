// Correct a result: edit the plan as a form (phases, their timing and controls' targets) or
// as raw JSON, see the server's validation inline (each issue at its field and line), and
// run it as a new job (POST /v1/animations with plan: executor and exporters only).

import { api } from "./api.js";
import { errorBox, fill, h } from "./dom.js";
import { jsonLines, lineOf, parseErrorLine } from "./json_paths.js";

const PHASE_TYPES = ["control_actuation", "causal_latency", "control_release", "effect_motion", "settle", "hold"];
const CURVES = ["linear", "ease_in", "ease_out", "ease_in_out"];
const FIELDS = {
  joint_position: [["q_target_expr", "text"], ["q_target_rad", "number"], ["q_start_rad", "number"], ["curve", CURVES]],
  joint_velocity: [["omega_radps", "number"], ["ramp_to_omega_radps", "number"]],
  hold_position: [],
  spring_return: [["spring_k", "number"], ["damping_c", "number"], ["rest_position", "number"]],
  base_velocity: [["axis_world", "axis"], ["v_mps", "number"]],
  base_velocity_decay: [["axis_world", "axis"], ["v0_mps", "number"], ["tau_s", "number"]],
  mode_set: [["name", "text"], ["set", "bool"]],
};
const CHECK_DELAY_MS = 350;

export class PlanEditor {
  constructor(job, plan, joints, { onSubmitted }) {
    this.job = job;
    this.joints = joints;
    this.onSubmitted = onSubmitted;
    this.plan = structuredClone(plan);
    this.valid = false;
    this.form = h("div", { class: "plan-form" });
    this.textarea = h("textarea", { testid: "plan-json", spellcheck: false, oninput: () => this.fromText() });
    this.issues = h("ul", { class: "issues", testid: "plan-issues" });
    this.run = h("button", { type: "button", testid: "run-plan", onclick: () => this.submit() }, "Run this plan as a new job");
    this.message = h("div");
    this.element = h("div", { testid: "plan-editor" },
      h("p", { class: "muted" }, "Edit the phases and targets (or the JSON), then run: the new job executes this plan as given — no perceiver, planner or critic."),
      h("div", { class: "row" }, this.run), this.message,
      h("div", { class: "editor-grid" },
        h("div", {}, h("h3", {}, "Phases and targets"), this.form),
        h("div", {}, h("h3", {}, "Plan.json"), this.issues, h("div", { class: "json-wrap" }, this.textarea))));
    this.textarea.value = JSON.stringify(this.plan, null, 2);
    this.renderForm();
    this.scheduleCheck();
  }

  input(path, value, kind, options = {}) {
    let element;
    if (Array.isArray(kind)) {
      element = h("select", {}, (options.optional ? [""] : []).concat(kind).map((v) => h("option", { value: v }, v || "–")));
      element.value = value ?? "";
    } else if (kind === "bool") {
      element = h("input", { type: "checkbox", checked: Boolean(value) });
    } else {
      element = h("input", { type: kind === "number" ? "number" : "text", step: "any", value: value ?? "" });
    }
    element.dataset.path = path;
    element.addEventListener("change", () => this.fromForm(element, kind));
    return h("label", { class: "field" }, h("span", {}, path.split(".").pop()), element, h("span", { class: "field-error" }));
  }

  renderForm() {
    const plan = this.plan;
    const jointNames = this.joints.map((j) => j.name);
    fill(this.form,
      h("div", { class: "row" },
        this.input("meta.fps", String(plan.meta?.fps ?? 30), ["24", "30"]),
        this.input("meta.duration_s", plan.meta?.duration_s, "number")),
      (plan.timeline || []).map((segment, s) => h("div", { class: "phase-form", dataset: { segment: String(s) } },
        h("div", { class: "row" },
          this.input(`timeline[${s}].name`, segment.name, "text"),
          this.input(`timeline[${s}].phase_type`, segment.phase_type, PHASE_TYPES),
          this.input(`timeline[${s}].t0`, segment.t0, "number"),
          this.input(`timeline[${s}].t1`, segment.t1, "number"),
          h("button", { type: "button", class: "secondary", onclick: () => this.removeSegment(s) }, "remove phase")),
        (segment.controls || []).map((control, c) => {
          const base = `timeline[${s}].controls[${c}]`;
          return h("div", { class: "ctl", dataset: { control: `${s}.${c}` } },
            h("b", {}, control.mode),
            "joint" in control ? this.input(`${base}.joint`, control.joint, jointNames.includes(control.joint) ? jointNames : [control.joint, ...jointNames]) : null,
            (FIELDS[control.mode] || []).map(([field, kind]) => this.input(`${base}.${field}`, kind === "axis" ? (control[field] || []).join(" ") : control[field], kind === "axis" ? "text" : kind, { optional: true })),
            h("button", { type: "button", class: "secondary", onclick: () => this.removeControl(s, c) }, "×"));
        }))));
  }

  set(path, value) {
    const parts = path.replace(/\[(\d+)\]/g, ".$1").split(".");
    let node = this.plan;
    for (const part of parts.slice(0, -1)) node = node[part];
    const last = parts[parts.length - 1];
    if (value === undefined) delete node[last]; else node[last] = value;
  }

  fromForm(element, kind) {
    const path = element.dataset.path;
    let value;
    if (kind === "bool") value = element.checked;
    else if (kind === "number") value = element.value === "" ? undefined : Number(element.value);
    else if (path.endsWith("axis_world")) value = element.value.trim().split(/[\s,]+/).map(Number);
    else if (path === "meta.fps") value = Number(element.value);
    else value = element.value === "" ? undefined : element.value;
    this.set(path, value);
    this.textarea.value = JSON.stringify(this.plan, null, 2);
    this.scheduleCheck();
  }

  removeSegment(index) {
    this.plan.timeline.splice(index, 1);
    this.afterStructureChange();
  }

  removeControl(segment, index) {
    this.plan.timeline[segment].controls.splice(index, 1);
    this.afterStructureChange();
  }

  afterStructureChange() {
    this.textarea.value = JSON.stringify(this.plan, null, 2);
    this.renderForm();
    this.scheduleCheck();
  }

  fromText() {
    let parsed;
    try {
      parsed = JSON.parse(this.textarea.value);
    } catch (error) {
      const { line, column } = parseErrorLine(this.textarea.value, error);
      this.showIssues([{ text: `not valid JSON${line ? ` at line ${line} column ${column}` : ""}: ${error.message}`, line }], []);
      this.valid = false;
      this.run.disabled = true;
      return;
    }
    this.plan = parsed;
    if (parsed && typeof parsed === "object" && Array.isArray(parsed.timeline)) this.renderForm();
    this.scheduleCheck();
  }

  scheduleCheck() {
    clearTimeout(this.pending);
    this.run.disabled = true;
    this.pending = setTimeout(() => this.check(), CHECK_DELAY_MS);
  }

  async check() {
    const text = this.textarea.value;
    let result;
    try {
      result = await api(`/v1/assets/${this.job.asset_id}/plan-check`, { method: "POST", json: this.plan });
    } catch (error) {
      this.showIssues([{ text: error.message, line: null }], []);
      return;
    }
    if (text !== this.textarea.value) return; // edited meanwhile: a newer check follows
    const lines = jsonLines(text);
    const located = (message) => {
      const path = message.split(":")[0];
      return { text: message, path, line: lineOf(lines, path) };
    };
    this.valid = result.valid;
    this.run.disabled = !result.valid;
    this.showIssues(result.issues.map(located), result.warnings.map(located));
  }

  showIssues(issues, warnings) {
    for (const element of this.form.querySelectorAll(".invalid")) element.classList.remove("invalid");
    for (const element of this.form.querySelectorAll(".field-error")) element.textContent = "";
    for (const issue of issues) {
      const input = issue.path && this.form.querySelector(`[data-path="${CSS.escape(issue.path)}"]`);
      if (input) {
        input.classList.add("invalid");
        input.parentElement.querySelector(".field-error").textContent = issue.text.slice(issue.path.length + 1).trim();
      }
    }
    this.textarea.classList.toggle("invalid", issues.length > 0);
    const item = (entry, kind) => h("li", {
      class: kind, dataset: entry.line ? { line: String(entry.line) } : {}, onclick: () => entry.line && this.selectLine(entry.line),
    }, entry.line ? `line ${entry.line}: ` : "", entry.text);
    fill(this.issues,
      issues.length || warnings.length ? null : h("li", { class: "muted" }, "valid: ready to run"),
      issues.map((entry) => item(entry, "issue")), warnings.map((entry) => item(entry, "warn")));
  }

  selectLine(line) {
    const lines = this.textarea.value.split("\n");
    const start = lines.slice(0, line - 1).reduce((sum, text) => sum + text.length + 1, 0);
    this.textarea.focus();
    this.textarea.setSelectionRange(start, start + (lines[line - 1] || "").length);
  }

  async submit() {
    fill(this.message);
    const data = new FormData();
    data.append("asset_ref", this.job.asset_id);
    data.append("plan", this.textarea.value);
    data.append("prompt", `edited plan of ${this.job.id.slice(0, 8)}: ${this.job.prompt}`.slice(0, 2000));
    this.run.disabled = true;
    try {
      this.onSubmitted(await api("/v1/animations", { method: "POST", body: data }));
    } catch (error) {
      fill(this.message, errorBox(error.message));
      this.run.disabled = !this.valid;
    }
  }
}
