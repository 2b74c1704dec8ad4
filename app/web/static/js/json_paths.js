// Where each value of a JSON text starts: "timeline[0].controls[1].joint" -> line number,
// so a validation issue naming a field can point at its line in the raw editor.

export function jsonLines(text) {
  const lines = new Map();
  let index = 0;
  let line = 1;
  const skip = () => {
    while (index < text.length && /\s/.test(text[index])) {
      if (text[index] === "\n") line += 1;
      index += 1;
    }
  };
  const string = () => {
    const start = index;
    index += 1;
    while (index < text.length && text[index] !== '"') index += text[index] === "\\" ? 2 : 1;
    index += 1;
    return JSON.parse(text.slice(start, index));
  };
  const value = (path) => {
    skip();
    lines.set(path || "(document)", line);
    const char = text[index];
    if (char === "{") {
      index += 1;
      skip();
      if (text[index] === "}") { index += 1; return; }
      for (;;) {
        skip();
        const key = string();
        skip();
        index += 1; // ':'
        value(path ? `${path}.${key}` : key);
        skip();
        if (text[index] === ",") { index += 1; continue; }
        index += 1; // '}'
        return;
      }
    }
    if (char === "[") {
      index += 1;
      skip();
      if (text[index] === "]") { index += 1; return; }
      for (let item = 0; ; item += 1) {
        value(`${path}[${item}]`);
        skip();
        if (text[index] === ",") { index += 1; continue; }
        index += 1; // ']'
        return;
      }
    }
    if (char === '"') { string(); return; }
    while (index < text.length && !/[\s,\]}]/.test(text[index])) index += 1;
  };
  value("");
  return lines;
}

/** Line of the longest known prefix of path (an issue may name a field that is absent). */
export function lineOf(lines, path) {
  let probe = path;
  while (probe) {
    if (lines.has(probe)) return lines.get(probe);
    const cut = Math.max(probe.lastIndexOf("."), probe.lastIndexOf("["));
    probe = cut > 0 ? probe.slice(0, cut) : "";
  }
  return lines.get("(document)") || 1;
}

/** Line and column of a JSON.parse error, from its message or position. */
export function parseErrorLine(text, error) {
  const position = /position (\d+)/.exec(error.message);
  const lineColumn = /line (\d+) column (\d+)/.exec(error.message);
  if (lineColumn) return { line: Number(lineColumn[1]), column: Number(lineColumn[2]) };
  if (!position) return { line: null, column: null };
  const before = text.slice(0, Number(position[1]));
  const line = before.split("\n").length;
  return { line, column: Number(position[1]) - before.lastIndexOf("\n") };
}
