// The viewer's page, HTML, style and script in one string: controls, the frame loop, orbit and zoom, animation
// and cameras; the oracle check's script (viewer_check_script.h) and the self-test's (viewer_self_test.h) go
// where the page marks them.
#include "apps/viewer_page.h"

#include <utility>

#include "apps/viewer_check_script.h"
#include "apps/viewer_self_test.h"

namespace raster::cli {
namespace {

constexpr const char* kPage = R"PAGE(<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>raster view</title>
<style>
  body { font: 14px/1.4 system-ui, sans-serif; margin: 0; background: #1b1c20; color: #e6e6e6; }
  header { padding: 8px 16px; border-bottom: 1px solid #333; }
  main { display: flex; flex-wrap: wrap; gap: 16px; padding: 16px; align-items: flex-start; }
  .column { max-width: 100%; }
  #check { margin-top: 12px; max-width: 640px; }
  #stage { position: relative; display: inline-block; max-width: 100%; line-height: 0; }
  #frame { display: block; max-width: 100%; background: #000; cursor: grab; touch-action: none; user-select: none; }
  #overlay { position: absolute; left: 0; top: 0; width: 100%; height: 100%; pointer-events: none;
             image-rendering: pixelated; }
  .swatch { display: inline-block; width: 0.9em; height: 0.9em; vertical-align: middle; margin-right: 0.4em; }
  #check-legend div { font-size: 12px; }
  #frame.dragging { cursor: grabbing; }
  aside { width: 280px; }
  fieldset { border: 1px solid #444; margin: 0 0 12px; }
  button { margin: 2px; padding: 4px 8px; background: #2c2e35; color: inherit; border: 1px solid #555;
           border-radius: 3px; cursor: pointer; }
  button[aria-pressed="true"] { background: #3d6bd6; border-color: #3d6bd6; }
  button:disabled { opacity: 0.4; cursor: default; }
  .readout { font-variant-numeric: tabular-nums; }
  .note { color: #999; font-size: 12px; }
  #status { color: #f08080; white-space: pre-wrap; }
  #selftest { margin: 0 16px 16px; white-space: pre-wrap; word-break: break-all; font-size: 11px; }
</style>
</head>
<body>
<header><strong>raster view</strong> <span id="scene"></span></header>
<main>
  <div class="column">
  <div id="stage"><img id="frame" alt="the rendered frame" draggable="false"><img id="overlay" alt="the oracle's disagreement map over the frame" hidden></div>
    <fieldset id="check"><legend>Oracle check</legend>
      <button type="button" id="check-run">check this frame</button>
      <label><input type="checkbox" id="check-overlay" checked disabled> overlay the disagreement map</label>
      <div class="readout" id="check-result"></div>
      <div id="check-legend"></div>
      <div class="note">Renders the frame again through raster render's job and casts the Embree oracle's rays at
        every sample, as raster compare does: seconds for a large frame.</div></fieldset>
  </div>
  <aside>
    <fieldset id="shading"><legend>Shading</legend></fieldset>
    <fieldset id="samples"><legend>Samples per pixel</legend></fieldset>
    <fieldset><legend>Anti-aliasing</legend>
      <label><input type="checkbox" id="msaa"> MSAA: shade once per pixel per triangle</label></fieldset>
    <fieldset id="filter"><legend>Texture filter</legend><div class="note" id="filter-note"></div></fieldset>
    <fieldset id="shadows"><legend>Shadows</legend><div class="note" id="shadows-note"></div></fieldset>
    <fieldset id="transparency"><legend>Transparency</legend><div class="note" id="transparency-note"></div></fieldset>
    <fieldset id="animation" hidden><legend>Animation</legend>
      <button type="button" id="play" aria-pressed="false">play</button>
      <input type="range" id="time" min="0" max="1" step="0.01" aria-label="time">
      <span class="readout" id="time-readout"></span></fieldset>
    <fieldset><legend>Camera</legend>
      <div id="cameras"></div>
      <div class="readout" id="camera"></div>
      <button type="button" id="camera-reset">reset</button>
      <div class="note">Drag the image to orbit about the target, turn the wheel over it to zoom.</div></fieldset>
    <p class="readout">frame: <span id="frame-ms">-</span> ms <span class="note" id="frame-info"></span></p>
    <p id="status"></p>
  </aside>
</main>
<pre id="selftest" hidden></pre>
<script>
'use strict';
const SHADINGS = ['flat', 'gouraud', 'phong', 'blinn-phong', 'cel', 'gooch', 'unlit'];
const SAMPLES = [1, 4, 16];
const FILTERS = ['nearest', 'bilinear', 'trilinear', 'anisotropic'];
const SHADOWS = ['on', 'off'];  // every point and spot light casts shadows, or none does
const TRANSPARENCIES = ['sorted', 'weighted', 'opaque'];  // blended surfaces' mode, or every material opaque
const HEARTBEAT_MS = 3000;  // how often the page checks that the server is still there
const DEGREES_PER_PIXEL = 0.4;  // of drag
const MIN_PLAY_STEP = 1 / 30;  // seconds: a played frame's least step, and the least wall time between two
const ZOOM_PER_100_WHEEL = 1.1;  // distance factor per 100 units of wheel delta
const selftest = new URLSearchParams(location.search).get('selftest') === '1';
const $ = (id) => document.getElementById(id);
const image = $('frame');

// What the next frame asks for; filter, shadows and transparency null keep the scene's own.
// time null: the scene as loaded (a static scene, or an animated one not yet played or scrubbed).
// camera null: the one the scene was loaded with.
const view = {shading: 'blinn-phong', samples: 1, msaa: false, filter: null, yaw: 0, pitch: 0, distance: 1, time: null,
              camera: null, shadows: null, transparency: null};
// From GET /state: the elevation limit, the scene eye's own elevation, the distance range, the scene's filter.
const scene = {elevationLimit: 89, elevation: 0, distance: [0.05, 20], filter: 'none', textured: false, animation: null,
               cameras: [], loadedCamera: 0, shadows: false, canCastShadows: false, transparency: 'sorted',
               blended: false};
// Playing: the wall clock when the last frame was asked for, so the next advances by the time that passed.
let playing = false, playedAt = 0;
const frames = [];  // every frame shown: {params, index, ms, hash (self-test only)}
let rendering = false, renderWanted = false, idleWaiters = [], drag = null;
const shownUrls = new Map();  // img element -> the object URL it shows

const clamp = (x, low, high) => Math.min(high, Math.max(low, x));
const wrapDegrees = (x) => ((((x + 180) % 360) + 360) % 360) - 180;
const clampPitch = (pitch) => clamp(pitch, Math.max(-180, -scene.elevationLimit - scene.elevation),
                                   Math.min(180, scene.elevationLimit - scene.elevation));

function showStatus(text) { $('status').textContent = text; }

// The server stopped answering (raster view ended, or the connection broke): say so, and stop playing. The
// heartbeat clears the message when it answers again.
function serverGone(error) {
  document.body.dataset.server = 'gone';
  showStatus(`The server is gone: raster view has stopped, or the connection to it was lost (${error}). ` +
             'Start it again (raster view SCENE) and reload this page.');
  if (playing) setPlaying(false);
}

// GET /render's parameters for the current view (docs/viewer.md).
function renderParams() {
  const params = {shading: view.shading, samples: String(view.samples), msaa: view.msaa ? '1' : '0',
                  yaw: view.yaw.toFixed(2), pitch: view.pitch.toFixed(2), distance: view.distance.toFixed(4)};
  if (view.filter) params.filter = view.filter;
  if (view.time !== null) params.time = view.time.toFixed(3);
  if (view.camera !== null) params.camera = String(view.camera);
  if (view.shadows !== null) params.shadows = view.shadows;
  if (view.transparency !== null) params.transparency = view.transparency;
  return params;
}

// 64-bit FNV-1a, as the server hashes the PNG it sends (GET /log's png_fnv1a64).
function fnv1a64(bytes) {
  const prime = 0x100000001b3n, mask = (1n << 64n) - 1n;
  let hash = 0xcbf29ce484222325n;
  for (const byte of bytes) hash = ((hash ^ BigInt(byte)) * prime) & mask;
  return hash.toString(16).padStart(16, '0');
}

// Shows PNG bytes in an img element. Resolves on the load event, not img.decode(): Chromium's virtual time (the
// tests' --virtual-time-budget) waits for loads but not for decode(), and dumped the DOM in the middle of the
// self-test.
function showPng(element, bytes) {
  return new Promise((resolve, reject) => {
    const url = URL.createObjectURL(new Blob([bytes], {type: 'image/png'}));
    element.onload = () => {
      if (shownUrls.has(element)) URL.revokeObjectURL(shownUrls.get(element));
      shownUrls.set(element, url);
      resolve();
    };
    element.onerror = () => reject(new Error(`the ${element.id} is not an image the browser decodes`));
    element.src = url;
  });
}

// Renders until the frame shown is the current view's: one request at a time, and changes made meanwhile
// become one next request, so a fast drag never queues a backlog.
async function renderLoop() {
  rendering = true;
  while (renderWanted) {
    renderWanted = false;
    const params = renderParams();
    try {
      const response = await fetch('/render?' + new URLSearchParams(params), {cache: 'no-store'});
      if (!response.ok) {
        showStatus(`the server refused the frame (${response.status}): ${await response.text()}`);
        if (playing) setPlaying(false);
        continue;
      }
      const bytes = new Uint8Array(await response.arrayBuffer());
      await showPng(image, bytes);
      const frame = {params, index: Number(response.headers.get('X-Frame-Index')),
                     ms: Number(response.headers.get('X-Frame-Ms'))};
      if (selftest) frame.hash = fnv1a64(bytes);
      frames.push(frame);
      $('frame-ms').textContent = frame.ms.toFixed(1);
      const encodeMs = Number(response.headers.get('X-Encode-Ms')).toFixed(1);
      $('frame-info').textContent = `(server render; frame ${frame.index}, PNG encoding ${encodeMs} ms)`;
      showStatus('');
    } catch (error) {
      // fetch rejects with a TypeError when no server answers; anything else is this frame's own failure.
      if (error instanceof TypeError) serverGone(error);
      else showStatus(`the frame could not be shown: ${error}`);
      if (playing) setPlaying(false);
    }
  }
  rendering = false;
  if (playing) {
    // The next instant once 1/30 s has passed since this one was asked for: real time, never faster.
    setTimeout(() => { if (playing) advancePlay(); }, Math.max(0, playedAt + 1000 * MIN_PLAY_STEP - performance.now()));
    return;
  }
  const waiters = idleWaiters;
  idleWaiters = [];
  waiters.forEach((resolve) => resolve());
}

// Playing: the next instant, by the wall time since the last (at least MIN_PLAY_STEP), wrapping at the last key.
// Until the page first asks for an instant it shows the scene as loaded, taken as the first key.
function advancePlay() {
  const now = performance.now();
  const {start, end} = scene.animation;
  const step = Math.max(MIN_PLAY_STEP, (now - playedAt) / 1000);
  playedAt = now;
  const next = (view.time === null ? start : view.time) + step;
  view.time = next > end ? start + ((next - start) % Math.max(end - start, MIN_PLAY_STEP)) : next;
  requestFrame();
}

function setPlaying(on) {
  playing = on;
  $('play').setAttribute('aria-pressed', String(on));
  $('play').textContent = on ? 'pause' : 'play';
  if (on) {
    playedAt = performance.now();
    advancePlay();
  }
}

function requestFrame() {
  renderWanted = true;
  if (check.result && check.params !== JSON.stringify(renderParams())) checkIsStale();
  showControls();
  if (!rendering) renderLoop();
}

// Resolves once no frame is being rendered or wanted.
function idle() {
  return rendering || renderWanted ? new Promise((resolve) => idleWaiters.push(resolve)) : Promise.resolve();
}

/*CHECK*/

function markPressed(prefix, values, chosen) {
  for (const value of values) $(`${prefix}-${value}`).setAttribute('aria-pressed', String(value === chosen));
}

function showControls() {
  markPressed('shading', SHADINGS, view.shading);
  markPressed('samples', SAMPLES, view.samples);
  markPressed('filter', FILTERS, view.filter || scene.filter);
  markPressed('shadows', SHADOWS, view.shadows || (scene.shadows ? 'on' : 'off'));
  markPressed('transparency', TRANSPARENCIES, view.transparency || scene.transparency);
  $('msaa').checked = view.msaa;
  scene.cameras.forEach((name, i) => $(`camera-pick-${i}`).setAttribute(
    'aria-pressed', String(i === (view.camera === null ? scene.loadedCamera : view.camera))));
  if (scene.animation) {
    const time = view.time === null ? scene.animation.start : view.time;
    $('time').value = String(time);
    $('time-readout').textContent = `${time.toFixed(2)} s`;
  }
  $('camera').textContent =
    `yaw ${view.yaw.toFixed(1)}\u00b0, pitch ${view.pitch.toFixed(1)}\u00b0, distance ${view.distance.toFixed(2)}`;
}

function addButtons(fieldset, values, choose) {
  for (const value of values) {
    const button = document.createElement('button');
    button.type = 'button';
    button.id = `${fieldset}-${value}`;
    button.textContent = String(value);
    button.addEventListener('click', () => {
      choose(value);
      requestFrame();
    });
    $(fieldset).appendChild(button);
  }
}

function buildControls() {
  addButtons('shading', SHADINGS, (shading) => { view.shading = shading; });
  addButtons('samples', SAMPLES, (samples) => { view.samples = samples; });
  addButtons('filter', FILTERS, (filter) => { view.filter = filter; });
  addButtons('shadows', SHADOWS, (shadows) => { view.shadows = shadows; });
  addButtons('transparency', TRANSPARENCIES, (transparency) => { view.transparency = transparency; });
  $('msaa').addEventListener('change', (event) => {
    view.msaa = event.target.checked;
    requestFrame();
  });
  $('play').addEventListener('click', () => setPlaying(!playing));
  $('check-run').addEventListener('click', () => {
    if (playing) setPlaying(false);  // a check is of one frame
    runCheck();
  });
  $('check-overlay').addEventListener('change', (event) => {
    $('overlay').hidden = !event.target.checked || !check.result || check.params !== JSON.stringify(renderParams());
  });
  $('time').addEventListener('input', (event) => {
    setPlaying(false);
    view.time = Number(event.target.value);
    requestFrame();
  });
  $('camera-reset').addEventListener('click', () => {
    Object.assign(view, {yaw: 0, pitch: 0, distance: 1});
    requestFrame();
  });
  image.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    drag = {x: event.clientX, y: event.clientY, yaw: view.yaw, pitch: view.pitch};
    try {
      image.setPointerCapture(event.pointerId);
    } catch (error) {
      // A pointer the browser does not know (a scripted one) has nothing to capture; the drag works the same.
    }
    image.classList.add('dragging');
    event.preventDefault();
  });
  image.addEventListener('pointermove', (event) => {
    if (!drag) return;
    // Dragging right turns the scene right (the eye left, yaw down); dragging down tips its top towards you.
    view.yaw = wrapDegrees(drag.yaw - (event.clientX - drag.x) * DEGREES_PER_PIXEL);
    view.pitch = clampPitch(drag.pitch + (event.clientY - drag.y) * DEGREES_PER_PIXEL);
    requestFrame();
  });
  const endDrag = () => {
    drag = null;
    image.classList.remove('dragging');
  };
  image.addEventListener('pointerup', endDrag);
  image.addEventListener('pointercancel', endDrag);
  image.addEventListener('wheel', (event) => {
    event.preventDefault();
    const factor = Math.pow(ZOOM_PER_100_WHEEL, event.deltaY / 100);
    view.distance = clamp(view.distance * factor, scene.distance[0], scene.distance[1]);
    requestFrame();
  }, {passive: false});
}

/*SELF-TEST*/

async function start() {
  buildControls();
  try {
    const response = await fetch('/state', {cache: 'no-store'});
    const state = await response.json();
    Object.assign(view, {shading: state.scene_settings.shading, samples: state.scene_settings.samples,
                         msaa: state.scene_settings.msaa});
    Object.assign(scene, {elevationLimit: state.limits.elevation_degrees, elevation: state.camera.elevation_degrees,
                          distance: state.limits.distance, filter: state.scene_settings.filter,
                          textured: state.textured, animation: state.animation,
                          cameras: state.cameras.names, loadedCamera: state.cameras.loaded,
                          shadows: state.scene_settings.shadows, canCastShadows: state.scene_settings.can_cast_shadows,
                          transparency: state.scene_settings.transparency, blended: state.scene_settings.blended});
    $('scene').textContent = `${state.scene} (${state.width} x ${state.height})`;
  } catch (error) {
    serverGone(error);
    document.body.dataset.selftest = 'fail';
    return;
  }
  document.body.dataset.server = 'up';
  setInterval(async () => {
    try {
      await fetch('/state', {cache: 'no-store'});
      if (document.body.dataset.server === 'gone') {
        document.body.dataset.server = 'up';
        showStatus('');
      }
    } catch (error) {
      serverGone(error);
    }
  }, HEARTBEAT_MS);
  if (!scene.textured) {
    for (const filter of FILTERS) $(`filter-${filter}`).disabled = true;
    $('filter-note').textContent = 'The scene has no textures: no filter changes it.';
  }
  if (!scene.canCastShadows) {
    for (const value of SHADOWS) $(`shadows-${value}`).disabled = true;
    $('shadows-note').textContent = 'The scene has no point or spot light: nothing casts shadows.';
  }
  if (!scene.blended) {
    for (const value of TRANSPARENCIES) $(`transparency-${value}`).disabled = true;
    $('transparency-note').textContent = 'No material of the scene is transparent.';
  }
  if (scene.cameras.length < 2) scene.cameras = [];  // one camera: nothing to pick
  scene.cameras.forEach((name, i) => {
    const button = document.createElement('button');
    Object.assign(button, {type: 'button', id: `camera-pick-${i}`, textContent: name});
    button.addEventListener('click', () => {
      Object.assign(view, {camera: i, yaw: 0, pitch: 0, distance: 1});
      requestFrame();
    });
    $('cameras').appendChild(button);
  });
  if (scene.animation) {
    const {start, end} = scene.animation;
    Object.assign($('time'), {min: String(start), max: String(end), value: String(start)});
    $('animation').hidden = false;
  }
  requestFrame();
  if (selftest) runSelfTest();
  else if (new URLSearchParams(location.search).get('check') === '1') idle().then(runCheck);  // a link that checks
}

start();
</script>
</body>
</html>
)PAGE";

}  // namespace

const std::string& viewer_page_html() {
    static const std::string page = [] {
        std::string text = kPage;
        for (const auto& [marker, script] : {std::pair{"/*SELF-TEST*/", viewer_self_test_script()},
                                             std::pair{"/*CHECK*/", viewer_check_script()}})
            text.replace(text.find(marker), std::string(marker).size(), script);
        return text;
    }();
    return page;
}

}  // namespace raster::cli
