// The plan as a phase timeline (one lane per phase type, a band per phase) and the joint
// values over time with their limits, both on the scrubber's time axis (same width and
// inset), with a playhead that follows the player.

import { h, number } from "./dom.js";

export const THUMB_INSET_PX = 7; // half the scrubber thumb: where t = 0 and t = end sit
const STRIP_PX = 64;
const COLORS = ["#2f6fde", "#e6863b", "#1f8a4c", "#8f7ad8", "#c0392b", "#2aa198", "#b7791f", "#d33682"];
const PHASE_ORDER = ["control_actuation", "causal_latency", "control_release", "effect_motion", "settle", "hold"];

function phaseColor(type) {
  return getComputedStyle(document.documentElement).getPropertyValue(`--phase-${type}`).trim() || "#889";
}

export class PhaseTimeline {
  constructor({ onSeek }) {
    this.onSeek = onSeek;
    this.playhead = h("div", { class: "playhead" });
    this.lanes = h("div", { class: "timeline-lanes" });
    this.element = h("div", { class: "timeline", testid: "phase-timeline", style: `padding: 0 ${THUMB_INSET_PX}px` },
      h("div", { style: "position: relative" }, this.lanes, this.playhead));
  }

  /** plan: Plan.json; duration: seconds of the whole animation. */
  show(plan, duration) {
    this.duration = duration;
    const segments = plan?.timeline || [];
    const types = [...new Set(segments.map((s) => s.phase_type))].sort((a, b) => PHASE_ORDER.indexOf(a) - PHASE_ORDER.indexOf(b));
    this.lanes.replaceChildren(...types.map((type) => {
      const lane = h("div", { class: "lane", dataset: { phaseType: type } }, h("span", { class: "lane-label" }, type));
      segments.forEach((segment, index) => {
        if (segment.phase_type !== type) return;
        const left = (segment.t0 / duration) * 100;
        const width = Math.max(((Math.min(segment.t1, duration) - segment.t0) / duration) * 100, 0.4);
        const joints = (segment.controls || []).map((c) => c.joint || c.mode).join(", ");
        lane.append(h("div", {
          class: "band", style: `left: ${left}%; width: ${width}%; background: ${phaseColor(type)}`,
          title: `${segment.name} (${type}) ${number(segment.t0, 2)}–${number(segment.t1, 2)} s: ${joints}`,
          dataset: { segment: String(index), t0: String(segment.t0), t1: String(segment.t1) },
          onclick: () => this.onSeek(segment.t0),
        }, segment.name));
      });
      return lane;
    }));
    if (!segments.length) this.lanes.replaceChildren(h("p", { class: "muted" }, "no plan.json in this job"));
    this.setTime(0);
  }

  setTime(t) {
    if (!this.duration) return;
    this.playhead.style.left = `${(t / this.duration) * 100}%`;
  }
}

export class JointCurves {
  constructor() {
    this.canvas = h("canvas", { class: "curves", testid: "joint-curves" });
    this.element = h("div", { style: `padding: 0 ${THUMB_INSET_PX}px` }, this.canvas);
    this.time = 0;
    new ResizeObserver(() => this.draw()).observe(this.canvas);
  }

  /** frames: [{time_s, joint_angles}], joints: [{name, lower, upper, type}], duration: seconds. */
  show(frames, joints, duration) {
    this.frames = frames;
    this.joints = joints.filter((j) => frames.length && j.name in frames[0].joint_angles);
    this.duration = duration;
    this.canvas.style.height = `${Math.max(this.joints.length, 1) * STRIP_PX}px`;
    this.draw();
  }

  setTime(t) {
    this.time = t;
    this.draw();
  }

  draw() {
    const { canvas } = this;
    const width = canvas.clientWidth;
    const height = canvas.clientHeight;
    if (!width || !height || !this.frames) return;
    const scale = window.devicePixelRatio || 1;
    canvas.width = width * scale;
    canvas.height = height * scale;
    const context = canvas.getContext("2d");
    context.scale(scale, scale);
    context.clearRect(0, 0, width, height);
    const x = (t) => (t / this.duration) * width;
    this.joints.forEach((joint, index) => {
      const top = index * STRIP_PX + 4;
      const strip = STRIP_PX - 10;
      const values = this.frames.map((f) => f.joint_angles[joint.name]);
      const bounded = joint.lower !== null && joint.lower !== undefined && joint.upper !== null && joint.upper !== undefined;
      let low = Math.min(...values, bounded ? joint.lower : Infinity);
      let high = Math.max(...values, bounded ? joint.upper : -Infinity);
      if (high - low < 1e-9) { low -= 0.5; high += 0.5; }
      const y = (v) => top + strip - ((v - low) / (high - low)) * strip;
      context.fillStyle = "#f6f7f9";
      context.fillRect(0, top, width, strip);
      if (bounded) {
        context.strokeStyle = "#c0392b";
        context.setLineDash([4, 3]);
        for (const limit of [joint.lower, joint.upper]) {
          context.beginPath();
          context.moveTo(0, y(limit));
          context.lineTo(width, y(limit));
          context.stroke();
        }
        context.setLineDash([]);
      }
      context.strokeStyle = COLORS[index % COLORS.length];
      context.lineWidth = 2;
      context.beginPath();
      this.frames.forEach((frame, i) => {
        const px = x(frame.time_s);
        const py = y(frame.joint_angles[joint.name]);
        if (i === 0) context.moveTo(px, py); else context.lineTo(px, py);
      });
      context.stroke();
      context.lineWidth = 1;
      context.fillStyle = "#1c2333";
      context.font = "11px system-ui, sans-serif";
      const limits = bounded ? ` [${number(joint.lower, 2)}, ${number(joint.upper, 2)}]` : " (no limits)";
      context.fillText(`${joint.name}${limits}`, 4, top + 11);
    });
    context.strokeStyle = "#d33";
    context.beginPath();
    context.moveTo(x(this.time), 0);
    context.lineTo(x(this.time), height);
    context.stroke();
  }
}
