// Small DOM helpers shared by the views.

/** Create an element: h("div", {class: "x", dataset: {testid: "y"}, onclick}, child, "text"). */
export function h(tag, attrs = {}, ...children) {
  const element = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs || {})) {
    if (value === undefined || value === null || value === false) continue;
    if (name === "dataset") Object.assign(element.dataset, value);
    else if (name === "testid") element.dataset.testid = value;
    else if (name.startsWith("on")) element.addEventListener(name.slice(2), value);
    else if (name === "class") element.className = value;
    else if (name in element && typeof value !== "string") element[name] = value;
    else element.setAttribute(name, value === true ? "" : value);
  }
  append(element, children);
  return element;
}

function append(element, children) {
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    element.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
}

/** Replace the children of an element. */
export function fill(element, ...children) {
  element.replaceChildren();
  append(element, children);
  return element;
}

export function $(selector, root = document) {
  return root.querySelector(selector);
}

export function number(value, digits = 3) {
  if (value === null || value === undefined || Number.isNaN(value)) return "–";
  return Number(value).toFixed(digits);
}

export function seconds(value) {
  if (value === null || value === undefined) return "–";
  return value < 1 ? `${(value * 1000).toFixed(1)} ms` : `${value.toFixed(2)} s`;
}

export function when(iso) {
  if (!iso) return "–";
  const date = new Date(iso);
  return date.toLocaleString(undefined, { month: "short", day: "numeric", hour: "2-digit", minute: "2-digit", second: "2-digit" });
}

export function bytes(size) {
  if (size < 1024) return `${size} B`;
  if (size < 1024 * 1024) return `${(size / 1024).toFixed(1)} KB`;
  return `${(size / 1024 / 1024).toFixed(1)} MB`;
}

/** A value of any JSON shape as compact readable text. */
export function show(value) {
  if (value === null || value === undefined) return "–";
  if (typeof value === "string") return value;
  if (typeof value === "number") return Number.isInteger(value) ? String(value) : value.toFixed(4).replace(/0+$/, "0");
  return JSON.stringify(value);
}

const isObject = (value) => value !== null && typeof value === "object" && !Array.isArray(value);

/** A cell for any JSON value: lists of objects become nested tables, objects key: value lines. */
function cell(value) {
  if (Array.isArray(value) && value.length && value.every(isObject)) return genericTable(value);
  if (isObject(value)) return Object.entries(value).map(([key, item]) => h("div", {}, h("span", { class: "muted" }, `${key}: `), cell(item)));
  return show(value);
}

/** A table with one column per key found in any row (rows are plain objects, any nesting). */
export function genericTable(rows, { testid, emptyText = "nothing" } = {}) {
  if (!rows || rows.length === 0) return h("p", { class: "muted", testid }, emptyText);
  const keys = [];
  for (const row of rows) for (const key of Object.keys(row || {})) if (!keys.includes(key)) keys.push(key);
  return h("table", { class: "grid", testid },
    h("thead", {}, h("tr", {}, keys.map((key) => h("th", {}, key)))),
    h("tbody", {}, rows.map((row) => h("tr", {}, keys.map((key) => h("td", {}, cell(row?.[key])))))));
}

export function statusBadge(status) {
  return h("span", { class: `badge status-${status}` }, status);
}

export function errorBox(message) {
  return h("div", { class: "error", role: "alert" }, message);
}
