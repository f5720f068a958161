// max2code serve: the thin client (protocol version 6, docs/server.md). No build step, no library.
// It holds every body's motion segment and draws any frame from it at the display's own rate;
// the server sends a segment again only when an event changes it. Drawing follows
// max2code.render (render/raster.py, render/svg.py): same shapes, colours, time stamp.
"use strict";

const PROTOCOL = 6;
const KEYS = {ArrowLeft: "left", ArrowRight: "right", ArrowUp: "up", ArrowDown: "down",
              a: "left", d: "right", w: "up", s: "down"};
const canvas = document.getElementById("view");
const ctx = canvas.getContext("2d");
const statusLine = document.getElementById("status");
const params = new URLSearchParams(location.search);

const state = {
  joined: false, closed: null, room: params.get("room") || "main", bodies: {}, segs: {}, g: [0, 0],
  you: [], view: null, n: 0, seq: 0, offset: null, rtt: null, samples: [], late: null,
  lateMax: 0, received: 0, bytes: 0, refused: [], frozen: null, lastDrawn: null,
};
let ws = null;

function clientNow() { return performance.now() / 1000; }
// the server's clock, estimated from round trips as NTP does: offset = s - (c0 + c1) / 2,
// taking the sample of least round trip among the last eight (its error is at most rtt/2)
function serverNow() { return clientNow() + (state.offset === null ? 0 : state.offset); }

function send(message) {
  message.seq = state.seq++;
  ws.send(JSON.stringify(message));
}

function setSegment(seg, t, g) {
  // [id, x, y, angle, vx, vy, omega, ax, ay, alpha, jx, jy, ja] from time t; trailing zeros
  // left off; g given: a `fall` segment [id, x, y, angle, vx, vy, omega] whose acceleration is
  // the world's g
  const v = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0];
  const n = g ? 6 : 12;
  for (let k = 1; k < seg.length && k <= n; k++) v[k - 1] = seg[k];
  if (g) { v[6] = g[0]; v[7] = g[1]; }
  state.segs[seg[0]] = {t: t, v: v};
}

function setSegments(m) {
  for (const seg of m.seg) setSegment(seg, m.t, null);
  for (const seg of m.fall || []) setSegment(seg, m.t, state.g);
}

function poseAt(id, t) {
  const g = state.segs[id];
  if (!g) return null;
  // p + v s + a s^2/2 + j s^3/6 (the jerks j only in a held body's cubic: protocol 6)
  const s = t - g.t, v = g.v;
  return [v[0] + s * (v[3] + s * (0.5 * v[6] + v[9] * s / 6)),
          v[1] + s * (v[4] + s * (0.5 * v[7] + v[10] * s / 6)),
          v[2] + s * (v[5] + s * (0.5 * v[8] + v[11] * s / 6))];
}

function onMessage(text) {
  state.received++;
  state.bytes += text.length;
  const m = JSON.parse(text);
  if (m.type === "world") {
    if (m.v !== PROTOCOL) { fail("server speaks protocol " + m.v); return; }
    // bodies by id: only the live ones (a removed id is never sent again)
    state.bodies = {}; state.segs = {}; state.you = m.you; state.view = m.view;
    for (const b of m.bodies) state.bodies[b.id] = b;
    state.n = m.n;
    state.g = m.g || [0, 0];
    setSegments(m);
    if (state.offset === null) state.offset = m.t - clientNow();
    state.joined = true;
  } else if (m.type === "ev") {
    if (m.n !== state.n + 1) { fail("message " + m.n + " out of order after " + state.n); return; }
    state.n = m.n;
    // removals first (the bodies are dropped), then additions with their segments in seg
    for (const id of m.rm || []) { delete state.bodies[id]; delete state.segs[id]; }
    for (const b of m.add || []) state.bodies[b.id] = b;
    setSegments(m);
    // how late the event reached us (drawn from its exact time on regardless)
    state.late = serverNow() - m.t;
    state.lateMax = Math.max(state.lateMax, state.late);
  } else if (m.type === "pong") {
    const now = clientNow(), rtt = now - m.c;
    state.samples.push({rtt: rtt, offset: m.s - (m.c + now) / 2});
    if (state.samples.length > 8) state.samples.shift();
    const best = state.samples.reduce((a, b) => (b.rtt < a.rtt ? b : a));
    state.offset = best.offset; state.rtt = best.rtt;
  } else if (m.type === "refused") {
    state.refused.push(m.reason);
  } else if (m.type === "error") {
    fail(m.reason);
  }
}

function fail(reason) { state.closed = reason; if (ws) ws.close(); }

let pingId = 0;
function ping() {
  if (ws && ws.readyState === WebSocket.OPEN) send({type: "ping", id: pingId++, c: clientNow()});
}

function connect() {
  ws = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + "/ws?room="
                     + encodeURIComponent(state.room));   // the URL's room routes to its worker
  ws.onopen = () => {
    // events: false: the page draws from segments only, so the server leaves the event lists out
    send({type: "hello", v: PROTOCOL, room: state.room, name: params.get("name") || "", events: false});
    for (let k = 0; k < 5; k++) setTimeout(ping, 100 * k);
    setInterval(ping, 2000);
  };
  ws.onmessage = (e) => onMessage(e.data);
  ws.onclose = (e) => { if (!state.closed) state.closed = "closed (" + e.code + ") " + e.reason; };
}

// -- input ------------------------------------------------------------------------------------
const held = new Set();
function key(e, down) {
  const k = KEYS[e.key];
  if (!k || !state.you.length) return;
  e.preventDefault();
  if (down === held.has(k)) return;     // no auto-repeat: a key's state changes, or nothing is sent
  if (down) held.add(k); else held.delete(k);
  send({type: "key", body: state.you[0], key: k, down: down});
}
addEventListener("keydown", (e) => key(e, true));
addEventListener("keyup", (e) => key(e, false));
canvas.addEventListener("pointerdown", (e) => {
  if (!state.you.length || !state.view) return;
  const r = canvas.getBoundingClientRect();
  const [x, y] = toWorld(e.clientX - r.left, e.clientY - r.top);
  send({type: "point", body: state.you[0], x: x, y: y});
});

// -- drawing (View.to_pixel of max2code.render.model) -----------------------------------------
function scale() {
  const v = state.view;
  return Math.min(canvas.width / (v[2] - v[0]), canvas.height / (v[3] - v[1]));
}
function toPixel(x, y) {
  const v = state.view, s = scale();
  return [canvas.width / 2 + (x - (v[0] + v[2]) / 2) * s, canvas.height / 2 - (y - (v[1] + v[3]) / 2) * s];
}
function toWorld(px, py) {
  const v = state.view, s = scale();
  return [(px - canvas.width / 2) / s + (v[0] + v[2]) / 2, -(py - canvas.height / 2) / s + (v[1] + v[3]) / 2];
}
function contrast(colour) {
  if (!colour) return "#000000";
  const r = parseInt(colour.substr(1, 2), 16), g = parseInt(colour.substr(3, 2), 16), b = parseInt(colour.substr(5, 2), 16);
  return (0.299 * r + 0.587 * g + 0.114 * b) / 255 > 0.5 ? "#000000" : "#ffffff";
}

function drawBody(b, pose) {
  if (b.shape.parts) {                          // a compound: each part in the body's style
    for (const part of b.shape.parts) drawBody(Object.assign({}, b, {shape: part}), pose);
    return;
  }
  const c = Math.cos(pose[2]), sn = Math.sin(pose[2]), s = scale(), sh = b.shape;
  const px = (p) => toPixel(pose[0] + c * p[0] - sn * p[1], pose[1] + sn * p[0] + c * p[1]);
  ctx.lineJoin = "round"; ctx.lineCap = "round";
  ctx.beginPath();
  let area = true;
  if (sh.c) {                                   // circle
    const q = px(sh.c);
    ctx.arc(q[0], q[1], sh.r * s, 0, 2 * Math.PI);
  } else if (sh.p) {                            // polygon, rounded by r: filled and grown by a 2r stroke
    sh.p.forEach((v, k) => { const q = px(v); if (k) ctx.lineTo(q[0], q[1]); else ctx.moveTo(q[0], q[1]); });
    ctx.closePath();
  } else {                                      // segment (thin) or capsule (r > 0)
    const a = px(sh.s[0]), e = px(sh.s[1]);
    ctx.moveTo(a[0], a[1]); ctx.lineTo(e[0], e[1]);
    area = !!sh.r;
  }
  const grow = (sh.p || sh.s) && sh.r ? 2 * sh.r * s : 0;
  if (area && b.fill) {
    ctx.fillStyle = b.fill; ctx.strokeStyle = b.fill;
    if (sh.p) ctx.fill();
    if (grow) { ctx.lineWidth = grow; ctx.stroke(); }
    else if (sh.c) ctx.fill();
  }
  const line = b.stroke || (area ? null : b.fill);
  if (line && b.sw > 0 && !grow) {
    ctx.strokeStyle = line; ctx.lineWidth = area ? b.sw : Math.max(b.sw, 1); ctx.stroke();
  }
  if (sh.c && b.spoke) {
    const q = px(sh.c), rim = px([sh.c[0] + sh.r, sh.c[1]]);
    ctx.beginPath(); ctx.moveTo(q[0], q[1]); ctx.lineTo(rim[0], rim[1]);
    ctx.strokeStyle = b.stroke || contrast(b.fill); ctx.lineWidth = Math.max(b.sw, 1); ctx.stroke();
  }
}

function drawYou(id, pose) {                   // a ring around what you control
  const b = state.bodies[id], s = scale();
  const q = toPixel(pose[0], pose[1]);
  const r = (b.shape.r || 0) * s + 4;
  ctx.beginPath(); ctx.arc(q[0], q[1], r, 0, 2 * Math.PI);
  ctx.strokeStyle = "#d62728"; ctx.lineWidth = 2; ctx.stroke();
}

function draw(t) {
  ctx.fillStyle = "#ffffff";
  ctx.fillRect(0, 0, canvas.width, canvas.height);
  for (const b of Object.values(state.bodies)) {
    const pose = poseAt(b.id, t);
    if (pose) drawBody(b, pose);
  }
  for (const id of state.you) { const p = state.bodies[id] && poseAt(id, t); if (p) drawYou(id, p); }
  const stamp = "t = " + t.toFixed(3) + " s";
  const size = Math.max(10, Math.round(Math.min(canvas.width, canvas.height) / 32));
  ctx.font = size + "px sans-serif"; ctx.textBaseline = "top";
  const w = ctx.measureText(stamp).width;
  ctx.fillStyle = "#ffffff"; ctx.fillRect(3, 3, w + 6, size + 6);
  ctx.fillStyle = "#000000"; ctx.fillText(stamp, 6, 6);
  state.lastDrawn = t;
}

function frame() {
  if (state.joined && state.view && state.frozen === null) draw(serverNow());
  statusLine.textContent = status();
  requestAnimationFrame(frame);
}

function ms(x) { return x === null ? "-" : (1000 * x).toFixed(1) + " ms"; }
function status() {
  if (state.closed) return "disconnected: " + state.closed;
  if (!state.joined) return "connecting...";
  const you = state.you.length ? state.you.map((i) => (state.bodies[i] ? state.bodies[i].name : "removed")).join(", ") : "nothing (watching)";
  return "room " + state.room + "   t = " + serverNow().toFixed(3) + " s   round trip " + ms(state.rtt)
    + "   last event arrived " + ms(state.late) + " after its time   you control " + you
    + "   messages " + state.received + " (" + state.bytes + " bytes)";
}

// For tests (tests/server/test_browser.py): draw the frame of server time t and keep it.
window.m2c = {state: state, serverNow: serverNow, poseAt: poseAt, toPixel: toPixel,
              freeze(t) { state.frozen = t; draw(t); return t; }, thaw() { state.frozen = null; }};

connect();
requestAnimationFrame(frame);
