// The jobs list: status, prompt, asset, time; filter by status and text; open one.

import { api, isTerminal } from "./api.js";
import { fill, h, statusBadge, when } from "./dom.js";

const REFRESH_MS = 3000;
const STATUSES = ["", "queued", "running", "succeeded", "failed", "cancelled"];

export class JobsPanel {
  constructor(root, { assetName, onOpen }) {
    this.root = root;
    this.assetName = assetName;
    this.onOpen = onOpen;
    this.jobs = [];
    this.selected = null;
    this.timer = null;
    this.text = h("input", { type: "text", placeholder: "filter prompt or asset", oninput: () => this.draw() });
    this.status = h("select", { onchange: () => this.refresh() }, STATUSES.map((s) => h("option", { value: s }, s || "any status")));
    this.list = h("ul", { class: "jobs-list", testid: "jobs-list" });
    this.count = h("span", { class: "muted" });
    fill(root, h("h2", {}, "Jobs ", this.count), h("div", { class: "row" }, this.text, this.status), this.list);
  }

  async refresh() {
    clearTimeout(this.timer);
    try {
      const status = this.status.value ? `&status=${this.status.value}` : "";
      const page = await api(`/v1/animations?limit=100${status}`);
      this.jobs = page.data;
      this.count.textContent = `(${page.count})`;
      this.draw();
    } catch (error) {
      fill(this.list, h("li", { class: "muted" }, error.message));
    }
    if (this.jobs.some((job) => !isTerminal(job.status))) this.timer = setTimeout(() => this.refresh(), REFRESH_MS);
  }

  select(id) {
    this.selected = id;
    this.draw();
  }

  draw() {
    const needle = this.text.value.trim().toLowerCase();
    const shown = this.jobs.filter((job) => !needle
      || job.prompt.toLowerCase().includes(needle)
      || (this.assetName(job.asset_id) || "").toLowerCase().includes(needle));
    if (!shown.length) {
      fill(this.list, h("li", { class: "muted" }, this.jobs.length ? "no job matches" : "no jobs yet"));
      return;
    }
    fill(this.list, shown.map((job) => h("li", {
      class: job.id === this.selected ? "selected" : "", dataset: { jobId: job.id }, onclick: () => this.onOpen(job.id),
    },
    h("span", { class: "prompt", title: job.prompt }, statusBadge(job.status), " ", job.prompt),
    h("span", { class: "meta" }, `${this.assetName(job.asset_id) || job.asset_id.slice(0, 8)} · ${when(job.created_at)}`,
      job.batch_id ? ` · batch ${job.case_id || ""}` : ""))));
  }
}
