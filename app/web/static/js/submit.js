// The submit form: an uploaded asset (a .zip or the files of a folder) or an earlier one,
// a prompt, the provider and per-role models, fps, preview. A submitted job opens at once
// in the job view, which follows its progress.

import { api } from "./api.js";
import { $, errorBox, fill, h } from "./dom.js";

const PROVIDERS = ["offline", "openai", "gemini"];
const ROLES = ["perceiver", "planner", "critic"];

export class SubmitPanel {
  constructor(root, { onSubmitted }) {
    this.root = root;
    this.onSubmitted = onSubmitted;
    this.assets = [];
    this.render();
  }

  render() {
    this.files = h("input", { type: "file", testid: "asset-file", multiple: true, accept: ".zip,.urdf,.obj,.mtl,.stl,.dae,.glb,.gltf,.png,.jpg,.txt,.json" });
    this.folder = h("input", { type: "file", webkitdirectory: true, multiple: true, title: "choose an asset folder" });
    this.earlier = h("select", { id: "earlier-asset" }, h("option", { value: "" }, "— or an earlier asset —"));
    this.prompt = h("textarea", { testid: "prompt", rows: 3, placeholder: "press the pedal to open the bin" });
    this.provider = h("select", { name: "provider" }, PROVIDERS.map((p) => h("option", { value: p }, p)));
    this.models = Object.fromEntries(ROLES.map((role) => [role, h("input", { type: "text", placeholder: "default", name: `${role}_model` })]));
    this.fps = h("select", { name: "fps" }, h("option", { value: "" }, "planner's"), h("option", { value: "24" }, "24"), h("option", { value: "30" }, "30"));
    this.rounds = h("select", { name: "max_critic_rounds" }, h("option", { value: "" }, "default"), [0, 1, 2, 3].map((n) => h("option", { value: String(n) }, String(n))));
    this.preview = h("input", { type: "checkbox", name: "preview" });
    this.button = h("button", { type: "submit", testid: "submit" }, "Animate");
    this.message = h("div");
    const form = h("form", { onsubmit: (event) => { event.preventDefault(); this.submit(); } },
      h("h2", {}, "New animation"),
      h("label", { class: "field" }, h("span", {}, "Asset: a .zip, or the URDF and its meshes"), this.files),
      h("label", { class: "field" }, h("span", {}, "…or a whole folder"), this.folder),
      h("label", { class: "field" }, this.earlier),
      h("label", { class: "field" }, h("span", {}, "Prompt"), this.prompt),
      h("details", {},
        h("summary", { class: "muted" }, "Provider, models, fps, preview"),
        h("label", { class: "field" }, h("span", {}, "Provider"), this.provider),
        ROLES.map((role) => h("label", { class: "field" }, h("span", {}, `${role} model`), this.models[role])),
        h("div", { class: "row" },
          h("label", { class: "field" }, h("span", {}, "fps"), this.fps),
          h("label", { class: "field" }, h("span", {}, "critic rounds"), this.rounds),
          h("label", { class: "field" }, h("span", {}, "preview.gif"), this.preview))),
      h("div", { class: "row" }, this.button), this.message);
    fill(this.root, form);
  }

  async loadAssets() {
    try {
      this.assets = (await api("/v1/assets?limit=100")).data;
    } catch {
      this.assets = [];
    }
    fill(this.earlier, h("option", { value: "" }, "— or an earlier asset —"),
      this.assets.map((a) => h("option", { value: a.id }, `${a.filename} (${a.sha256.slice(0, 8)})`)));
    return this.assets;
  }

  assetName(id) {
    return this.assets.find((a) => a.id === id)?.filename;
  }

  formData() {
    const data = new FormData();
    const picked = [...this.files.files, ...this.folder.files];
    if (picked.length) {
      for (const file of picked) data.append("asset", file, file.webkitRelativePath || file.name);
    } else if (this.earlier.value) {
      data.append("asset_ref", this.earlier.value);
    } else {
      throw new Error("choose an asset: a .zip, the files of a folder, or an earlier asset");
    }
    const prompt = this.prompt.value.trim();
    if (!prompt) throw new Error("write a prompt: what should happen");
    data.append("prompt", prompt);
    if (this.provider.value !== "offline") data.append("provider", this.provider.value);
    for (const role of ROLES) if (this.models[role].value.trim()) data.append(`${role}_model`, this.models[role].value.trim());
    if (this.fps.value) data.append("fps", this.fps.value);
    if (this.rounds.value) data.append("max_critic_rounds", this.rounds.value);
    if (this.preview.checked) data.append("preview", "true");
    return data;
  }

  async submit() {
    fill(this.message);
    let data;
    try {
      data = this.formData();
    } catch (error) {
      fill(this.message, errorBox(error.message));
      return;
    }
    this.button.disabled = true;
    this.button.textContent = "Uploading…";
    try {
      const accepted = await api("/v1/animations", { method: "POST", body: data });
      this.files.value = "";
      this.folder.value = "";
      this.onSubmitted(accepted);
      this.loadAssets();
    } catch (error) {
      fill(this.message, errorBox(error.message));
    } finally {
      this.button.disabled = false;
      this.button.textContent = "Animate";
    }
  }
}

export function selectAsset(panel, id) {
  const option = $(`option[value="${id}"]`, panel.earlier);
  if (option) panel.earlier.value = id;
}
