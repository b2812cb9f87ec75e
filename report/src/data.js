// The page's data: the JSON in <script id="yardsim-data">, arrays as base64 float32.
export function readData() {
  const el = document.getElementById('yardsim-data');
  if (!el) throw new Error('yardsim report: no <script id="yardsim-data"> in the page');
  return JSON.parse(el.textContent);
}

// (base64) => bytes
export function bytes(b64) {
  const bin = atob(b64);
  const out = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

// (base64 of little-endian float32) => Float32Array
export function float32(b64) {
  const b = bytes(b64);
  return new Float32Array(b.buffer, b.byteOffset, b.byteLength / 4);
}

// (number, digits) => short text
export function fmt(x, digits = 4) {
  if (x === null || x === undefined || !Number.isFinite(x)) return '–';
  const a = Math.abs(x);
  if (a !== 0 && (a >= 1e6 || a < 1e-3)) return x.toExponential(digits - 1);
  return Number(x.toPrecision(digits)).toString();
}

// (tag, attributes, children) => element
export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === 'class') e.className = v;
    else if (k === 'style') e.style.cssText = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}
