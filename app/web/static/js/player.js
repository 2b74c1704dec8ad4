// The job's animation.glb in three.js: GLTFLoader + AnimationMixer, orbit controls, a ground
// grid, world axes (URDF frame, Z up) with a corner gizmo, link names on hover with the
// link highlighted. Time is driven from outside (play/pause/speed/scrubber call setTime).

import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { h } from "./dom.js";

const HIGHLIGHT = new THREE.Color(0x2f6fde);
const GIZMO_PX = 96;
const MAX_STEP_S = 0.5; // a longer pause between frames (hidden tab) does not jump ahead

function label(text, color) {
  const canvas = document.createElement("canvas");
  canvas.width = canvas.height = 64;
  const context = canvas.getContext("2d");
  context.fillStyle = color;
  context.font = "bold 44px sans-serif";
  context.textAlign = "center";
  context.textBaseline = "middle";
  context.fillText(text, 32, 34);
  const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: new THREE.CanvasTexture(canvas), depthTest: false }));
  sprite.scale.setScalar(0.45);
  return sprite;
}

/** World axes of the URDF frame (X red, Y green, Z blue; Z up), drawn in the glTF's Y-up scene. */
function urdfAxes(size, withLabels) {
  const group = new THREE.Group();
  group.rotation.x = -Math.PI / 2; // URDF Z-up -> glTF Y-up, as artimo_root does
  group.add(new THREE.AxesHelper(size));
  if (withLabels) {
    for (const [text, color, position] of [["X", "#d33", [1, 0, 0]], ["Y", "#2a2", [0, 1, 0]], ["Z", "#35d", [0, 0, 1]]]) {
      const sprite = label(text, color);
      sprite.position.set(...position.map((v) => v * size * 1.25));
      group.add(sprite);
    }
  }
  return group;
}

export class Player {
  constructor({ onTime } = {}) {
    this.onTime = onTime || (() => {});
    this.canvas = h("canvas", { testid: "viewer-canvas" });
    this.tip = h("div", { class: "tip" });
    this.element = h("div", { class: "viewer" }, this.canvas, this.tip,
      h("div", { class: "legend" }, "world axes (URDF, Z up): ", h("b", { class: "x" }, "X"), " ", h("b", { class: "y" }, "Y"), " ",
        h("b", { class: "z" }, "Z"), " · grid 0.1 m"));
    this.time = 0;
    this.duration = 0;
    this.speed = 1;
    this.playing = false;
    this.linkOf = new Map(); // mesh -> link object
    this.links = new Map(); // link name -> object
    this.hovered = null;
    this.last = performance.now();
    this.setup();
  }

  setup() {
    this.renderer = new THREE.WebGLRenderer({ canvas: this.canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    this.renderer.setClearColor(0xe9edf3);
    this.renderer.autoClear = false;
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8890a0, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 2.0);
    sun.position.set(2, 4, 3);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = true;
    this.gizmoScene = new THREE.Scene();
    this.gizmoScene.add(urdfAxes(1, true));
    this.gizmoCamera = new THREE.OrthographicCamera(-1.8, 1.8, 1.8, -1.8, 0.1, 10);
    this.raycaster = new THREE.Raycaster();
    this.pointer = null;
    this.canvas.addEventListener("pointermove", (event) => this.hover(event));
    this.canvas.addEventListener("pointerleave", () => this.setHovered(null));
    new ResizeObserver(() => this.resize()).observe(this.canvas);
    this.renderer.setAnimationLoop(() => this.frame());
  }

  resize() {
    const { clientWidth: width, clientHeight: height } = this.canvas;
    if (!width || !height) return;
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
  }

  /** Load a GLB (ArrayBuffer); resolves once the scene is shown at t = 0. */
  async load(buffer) {
    const gltf = await new GLTFLoader().parseAsync(buffer, "");
    this.model = gltf.scene;
    this.scene.add(this.model);
    this.model.traverse((object) => {
      if ("joint" in (object.userData || {})) this.links.set(object.name, object);
    });
    this.model.traverse((object) => {
      if (!object.isMesh) return;
      let owner = object;
      while (owner && !this.links.has(owner.name)) owner = owner.parent;
      if (owner) this.linkOf.set(object, owner);
      object.userData.baseMaterial = object.material;
    });
    const clip = gltf.animations.find((a) => a.name === "action") || gltf.animations[0];
    this.mixer = new THREE.AnimationMixer(this.model);
    if (clip) {
      this.action = this.mixer.clipAction(clip);
      this.action.play();
      this.duration = clip.duration;
    }
    this.setTime(0);
    this.frameScene();
    return { duration: this.duration, links: [...this.links.keys()], joints: this.joints() };
  }

  /** Joint records from the GLB's node extras: [{name, type, lower, upper, link}]. */
  joints() {
    const result = [];
    for (const [link, object] of this.links) {
      const joint = object.userData.joint;
      if (joint && joint.type !== "fixed") result.push({ ...joint, link });
    }
    return result;
  }

  frameScene() {
    const box = new THREE.Box3().setFromObject(this.model);
    const size = box.getSize(new THREE.Vector3());
    const center = box.getCenter(new THREE.Vector3());
    const diagonal = Math.max(size.length(), 0.05);
    const extent = Math.max(1, Math.ceil(diagonal * 3));
    const grid = new THREE.GridHelper(extent, extent * 10, 0x9aa3b5, 0xc9ceda);
    grid.position.y = box.min.y;
    this.scene.add(grid);
    this.scene.add(urdfAxes(diagonal * 0.35, false));
    const direction = new THREE.Vector3(1.1, 0.75, 1.4).normalize();
    this.camera.position.copy(center).addScaledVector(direction, diagonal * 1.7);
    this.camera.near = diagonal / 100;
    this.camera.far = diagonal * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
  }

  setTime(t) {
    this.time = Math.min(Math.max(t, 0), this.duration || 0);
    if (this.action) {
      this.action.time = this.time; // set, not stepped: the mixer would wrap t = end to 0 when looping
      this.mixer.update(0);
    }
    this.onTime(this.time);
  }

  play() {
    if (this.time >= this.duration) this.setTime(0);
    this.playing = true;
    this.last = performance.now();
  }

  pause() {
    this.playing = false;
  }

  frame() {
    const now = performance.now();
    const delta = Math.min((now - this.last) / 1000, MAX_STEP_S);
    this.last = now;
    if (this.playing && this.duration > 0) {
      let next = this.time + delta * this.speed;
      if (next > this.duration) next = 0; // loop
      this.setTime(next);
    }
    this.controls.update();
    this.renderer.setScissorTest(false);
    this.renderer.clear();
    this.renderer.render(this.scene, this.camera);
    this.renderGizmo();
  }

  renderGizmo() {
    const { clientWidth: width } = this.canvas;
    if (!width) return;
    const offset = this.camera.position.clone().sub(this.controls.target).normalize().multiplyScalar(4);
    this.gizmoCamera.position.copy(offset);
    this.gizmoCamera.quaternion.copy(this.camera.quaternion);
    this.renderer.setScissorTest(true);
    this.renderer.setViewport(width - GIZMO_PX - 4, 4, GIZMO_PX, GIZMO_PX);
    this.renderer.setScissor(width - GIZMO_PX - 4, 4, GIZMO_PX, GIZMO_PX);
    this.renderer.clearDepth();
    this.renderer.render(this.gizmoScene, this.gizmoCamera);
    this.renderer.setViewport(0, 0, width, this.canvas.clientHeight);
    this.renderer.setScissorTest(false);
  }

  hover(event) {
    if (!this.model) return;
    const rect = this.canvas.getBoundingClientRect();
    const pointer = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(pointer, this.camera);
    const hit = this.raycaster.intersectObject(this.model, true).find((i) => this.linkOf.has(i.object));
    this.setHovered(hit ? this.linkOf.get(hit.object) : null);
    if (hit) {
      const link = this.linkOf.get(hit.object);
      const joint = link.userData.joint;
      this.tip.textContent = joint ? `${link.name} · ${joint.name} (${joint.type})` : `${link.name} · fixed`;
      this.tip.style.left = `${event.clientX - rect.left + 12}px`;
      this.tip.style.top = `${event.clientY - rect.top + 12}px`;
    }
  }

  /** Highlight one link's own meshes (not its child links'), or none. */
  setHovered(link) {
    if (link === this.hovered) return;
    this.hovered = link;
    this.tip.style.display = link ? "block" : "none";
    this.element.dataset.hoveredLink = link ? link.name : "";
    for (const [mesh, owner] of this.linkOf) {
      const base = mesh.userData.baseMaterial;
      if (owner !== link) {
        mesh.material = base;
        continue;
      }
      const lit = (material) => {
        const copy = material.clone();
        if (copy.emissive) copy.emissive.copy(HIGHLIGHT).multiplyScalar(0.6);
        else if (copy.color) copy.color.lerp(HIGHLIGHT, 0.5);
        return copy;
      };
      mesh.material = Array.isArray(base) ? base.map(lit) : lit(base);
    }
  }

  /** Screen position of a link's origin (for tests and tools). */
  linkScreenPosition(name) {
    const object = this.links.get(name);
    if (!object) return null;
    const box = new THREE.Box3();
    for (const [mesh, owner] of this.linkOf) if (owner === object) box.expandByObject(mesh);
    const point = box.isEmpty() ? object.getWorldPosition(new THREE.Vector3()) : box.getCenter(new THREE.Vector3());
    point.project(this.camera);
    return { x: (point.x + 1) / 2 * this.canvas.clientWidth, y: (1 - point.y) / 2 * this.canvas.clientHeight };
  }

  dispose() {
    this.renderer.setAnimationLoop(null);
    this.controls.dispose();
    this.renderer.dispose();
  }
}
