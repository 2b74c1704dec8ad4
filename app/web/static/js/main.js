// The page: key handling, routing (#/jobs, #/jobs/<id>, #/batches, #/batches/<id>) and the
// panels. Every call carries the key kept in this browser; a sign-in link (#login=...)
// printed by `artimo serve` stores its token as the key.

import { adoptLoginFromLocation, api, getKey, setKey } from "./api.js";
import { $, errorBox, fill, h } from "./dom.js";
import { showBatch, showBatchList } from "./batches.js";
import { JobView } from "./job_view.js";
import { JobsPanel } from "./jobs.js";
import { SubmitPanel } from "./submit.js";

const main = $("#main");
let view = null;

const submit = new SubmitPanel($("#submit-panel"), { onSubmitted: (accepted) => { location.hash = `#/jobs/${accepted.id}`; jobs.refresh(); } });
const jobs = new JobsPanel($("#jobs-panel"), { assetName: (id) => submit.assetName(id), onOpen: (id) => { location.hash = `#/jobs/${id}`; } });

function welcome() {
  fill(main, h("section", { class: "panel welcome" }, h("h2", {}, "ArtiMo"),
    h("p", {}, "Upload an articulated asset (URDF + meshes, as a .zip or a folder), say what should happen, and watch the result: ",
      "the animation with its joints, the plan's phases, what the agent understood, and what the critic changed. ",
      "Correct the plan and run it again."),
    getKey() ? h("p", { class: "muted" }, "Pick a job on the left, or submit a new one.")
      : h("p", {}, "First paste an API key above (", h("code", {}, "artimo keys create --name me"), "), or open the link ", h("code", {}, "artimo serve"), " prints.")));
}

async function route() {
  view?.close?.();
  view = null;
  delete main.dataset.loaded;
  const [section, id] = location.hash.replace(/^#\/?/, "").split("/");
  for (const link of document.querySelectorAll("[data-nav]")) link.classList.toggle("active", link.dataset.nav === (section || "jobs"));
  jobs.select(section === "jobs" ? id : null);
  try {
    if (section === "jobs" && id) {
      view = new JobView(main, id, { onSubmitted: (accepted) => { location.hash = `#/jobs/${accepted.id}`; jobs.refresh(); }, onChanged: () => jobs.refresh() });
      await view.open();
    } else if (section === "batches" && id) {
      await showBatch(main, id);
    } else if (section === "batches") {
      await showBatchList(main);
    } else {
      welcome();
    }
  } catch (error) {
    fill(main, h("section", { class: "panel" }, errorBox(error.message)));
  }
}

async function checkKey() {
  const state = $("#key-state");
  if (!getKey()) {
    state.textContent = "no key";
    return false;
  }
  try {
    await api("/v1/animations?limit=1");
    state.textContent = getKey().startsWith("artimo-page.") ? "signed in (link)" : "key ok";
    return true;
  } catch (error) {
    state.textContent = error.status === 401 ? "key refused" : error.message;
    return false;
  }
}

async function boot() {
  adoptLoginFromLocation();
  const input = $("#api-key");
  input.value = getKey();
  $("#key-form").addEventListener("submit", async (event) => {
    event.preventDefault();
    setKey(input.value);
    if (await checkKey()) { submit.loadAssets().then(() => jobs.refresh()); route(); }
  });
  window.addEventListener("hashchange", route);
  if (await checkKey()) {
    await submit.loadAssets();
    jobs.refresh();
  }
  route();
}

boot();
