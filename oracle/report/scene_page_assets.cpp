// The style and script of a scene's page (scene_page_assets.h).
#include "oracle/report/scene_page_assets.h"

namespace raster::oracle {

const char* scene_page_style() {
    return R"(
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
.verdict { font-size: 1.2em; font-weight: bold; }
.verdict.fail { color: #c00; }
.verdict.pass { color: #176317; }
.toolbar { margin: 0.8em 0; display: flex; gap: 0.5em; align-items: center; flex-wrap: wrap; }
.toolbar .readout { font-family: monospace; margin-left: 1em; }
.panes { display: flex; gap: 1em; flex-wrap: wrap; align-items: flex-start; }
.pane { margin: 0; }
.pane[hidden] { display: none; }
.frame { position: relative; overflow: hidden; width: min(30vw, 560px); background: #000; cursor: crosshair;
         touch-action: none; user-select: none; }
.frame img.view { position: absolute; left: 0; top: 0; transform-origin: 0 0; image-rendering: pixelated;
                  max-width: none; pointer-events: none; }
.pane figcaption { font-size: 0.9em; color: #444; margin-top: 0.3em; }
.swipe-slider { width: min(30vw, 560px); display: block; }
.legend span.swatch { display: inline-block; width: 0.9em; height: 0.9em; vertical-align: middle; margin: 0 0.3em 0 0.8em; }
table.counts { border-collapse: collapse; margin-top: 1em; }
.inspector h2 { font-size: 1.1em; margin: 1em 0 0.3em; }
table.samples { border-collapse: collapse; font-family: monospace; font-size: 0.9em; }
table.samples th, table.samples td { padding: 0.15em 0.7em; border-bottom: 1px solid #ddd; text-align: left; }
table.samples tr.genuine td.class { color: #c00; font-weight: bold; }
table.samples tr.ambiguous td.class { color: #9a7b00; }
table.counts td { padding: 0.15em 0.8em 0.15em 0; vertical-align: top; }
)";
}

const char* scene_page_script() {
    return R"(
const panes = document.querySelector('.panes');
const width = Number(panes.dataset.width), height = Number(panes.dataset.height);
const state = {scale: 1, x: 0, y: 0};
const visibleFrame = () => Array.from(document.querySelectorAll('.pane:not([hidden]) .frame'))[0];
function apply() {
  for (const image of document.querySelectorAll('img.view'))
    image.style.transform = 'translate(' + state.x + 'px, ' + state.y + 'px) scale(' + state.scale + ')';
  document.body.dataset.zoom = String(state.scale);
  document.body.dataset.pan = state.x + ',' + state.y;
  document.querySelector('.zoom-level').textContent = Math.round(state.scale * 100) + '%';
}
function fit() {
  state.scale = visibleFrame().clientWidth / width;
  state.x = 0;
  state.y = 0;
  apply();
}
// Zooms by `factor` keeping the image point under frame point (px, py) where it is.
function zoomAbout(factor, px, py) {
  const scale = Math.min(64, Math.max(0.05, state.scale * factor));
  state.x = px - (px - state.x) * scale / state.scale;
  state.y = py - (py - state.y) * scale / state.scale;
  state.scale = scale;
  apply();
}
function frameCentre() {
  const frame = visibleFrame();
  return [frame.clientWidth / 2, frame.clientHeight / 2];
}
// The colour disagreements the diff map carries for pixel (x, y), as text.
function disagreementsAt(x, y) {
  const diff = document.querySelector('img.diff');
  const list = JSON.parse((diff && diff.dataset.disagreements) || '[]');
  return list.filter(d => d.x === x && d.y === y).map(d =>
    d.file + ': raster ' + d.raster.join(' ') + ', allowed ' + d.allowed.map(r => r[0] + '-' + r[1]).join(' ') +
    ', oracle ' + d.oracle.join(' ')).join('; ');
}
// The inspector: the evidence the report wrote beside the page (window.rasterEvidence) for pixel (x, y): the pixel's
// state, its bytes on both sides with the interval allowed, its colour, shadow and layer verdicts, and a row per
// sample with the excuse's figure and bound. A pixel it does not list has every sample agreeing.
const genuineClasses = ['visibility', 'barycentrics', 'depth'];
const byteText = bytes => bytes ? bytes.join(' ') : 'not written';
function pixelSummary(x, y, p) {
  const lines = ['Pixel (' + x + ', ' + y + '): ' + p.state + ', ' + p.samples.length +
                 (p.samples.length === 1 ? ' sample.' : ' samples.'),
                 'raster ' + byteText(p.raster) + ', oracle ' + byteText(p.oracle) + ', allowed ' +
                 (p.allowed ? p.allowed.map(r => r[0] + '-' + r[1]).join(' ') : 'none: not judged (' + p.state + ')') + '.'];
  if (p.colour) lines.push('colour: ' + p.colour + '.');
  if (p.shadows) lines.push('shadow verdicts met: ' + (p.shadows.length ? p.shadows.join(', ') : 'none') + '.');
  if (p.layers !== undefined) lines.push('transparent layers: ' + (p.layers ? 'left open by ' + p.layers : 'decided') + '.');
  return lines.join(' ');
}
function showEvidence(x, y) {
  const status = document.querySelector('.inspector-status'), table = document.querySelector('table.samples');
  table.textContent = '';
  const evidence = window.rasterEvidence;
  if (!evidence) { status.textContent = 'No evidence file beside this page.'; return; }
  const pixel = (evidence.pixels || {})[x + ',' + y];
  if (!pixel) {
    status.textContent = 'Pixel (' + x + ', ' + y + '): every one of its ' + evidence.samples +
      ' samples agrees with the oracle and its colour is inside its interval' + (evidence.unlisted > 0 ?
      ' (or it is past the ' + evidence.listed + ' pixels listed; ' + evidence.unlisted + ' more were left out)' : '') + '.';
    return;
  }
  status.textContent = pixelSummary(x, y, pixel);
  const head = table.insertRow();
  for (const title of ['sample', 'class', 'raster triangle', 'raster barycentrics', 'raster depth',
                       'oracle triangle', 'oracle barycentrics', 'oracle depth', 'excuse', 'measured', 'bound']) {
    const th = document.createElement('th');
    th.textContent = title;
    head.appendChild(th);
  }
  pixel.samples.forEach((s, k) => {
    const row = table.insertRow();
    row.className = genuineClasses.includes(s[0]) ? 'genuine' : s[0] === 'agree' ? 'agree' : 'ambiguous';
    const cells = [k, s[0], s[1] < 0 ? 'none' : s[1], s[2].join(' '), s[3], s[4] < 0 ? 'none' : s[4], s[5].join(' '),
                   s[6], s[7], s[8] === null ? '-' : s[8], s[9] === null ? '-' : s[9]];
    cells.forEach((value, i) => {
      const td = row.insertCell();
      td.textContent = String(value);
      if (i === 1) td.className = 'class';
      if (i >= 9) td.className = i === 9 ? 'measured' : 'bound';
    });
  });
}
function readPixel(px, py) {
  const x = Math.floor((px - state.x) / state.scale), y = Math.floor((py - state.y) / state.scale);
  const inside = x >= 0 && y >= 0 && x < width && y < height;
  document.body.dataset.pixel = inside ? x + ',' + y : '';
  const found = inside ? disagreementsAt(x, y) : '';
  document.querySelector('.readout').textContent =
    inside ? '(' + x + ', ' + y + ')' + (found ? ' ' + found : ': no colour disagreement') : 'outside the image';
  if (inside) showEvidence(x, y);
}
for (const frame of document.querySelectorAll('.frame')) {
  frame.style.aspectRatio = width + ' / ' + height;
  frame.addEventListener('wheel', event => {
    event.preventDefault();
    const box = frame.getBoundingClientRect();
    zoomAbout(event.deltaY < 0 ? 1.25 : 0.8, event.clientX - box.left, event.clientY - box.top);
  }, {passive: false});
  let drag = null;
  frame.addEventListener('pointerdown', event => {
    drag = {x: event.clientX, y: event.clientY, moved: 0};
    if (frame.setPointerCapture && event.pointerId !== undefined) {
      try { frame.setPointerCapture(event.pointerId); } catch (e) {}
    }
  });
  frame.addEventListener('pointermove', event => {
    if (!drag) return;
    const dx = event.clientX - drag.x, dy = event.clientY - drag.y;
    drag.moved += Math.abs(dx) + Math.abs(dy);
    drag.x = event.clientX;
    drag.y = event.clientY;
    state.x += dx;
    state.y += dy;
    apply();
  });
  frame.addEventListener('pointerup', event => {
    if (drag && drag.moved < 3) {
      const box = frame.getBoundingClientRect();
      readPixel(event.clientX - box.left, event.clientY - box.top);
    }
    drag = null;
  });
}
for (const button of document.querySelectorAll('button[data-zoom]')) {
  button.addEventListener('click', () => {
    const action = button.dataset.zoom;
    if (action === 'fit') return fit();
    const [cx, cy] = frameCentre();
    if (action === 'in') zoomAbout(2, cx, cy);
    else if (action === 'out') zoomAbout(0.5, cx, cy);
    else zoomAbout(1 / state.scale, cx, cy);
  });
}
const swipeToggle = document.querySelector('.swipe-toggle'), swipePane = document.querySelector('.pane.swipe');
const slider = document.querySelector('.swipe-slider');
function setSwipe(share) {
  document.querySelector('.pane.swipe img.over').style.clipPath = 'inset(0 0 0 ' + share + '%)';
  document.body.dataset.swipe = String(share);
}
swipeToggle.addEventListener('change', () => {
  swipePane.hidden = !swipeToggle.checked;
  apply();
});
slider.addEventListener('input', () => setSwipe(Number(slider.value)));
setSwipe(Number(slider.value));
function markRendered() {
  const images = Array.from(document.querySelectorAll('img.view'));
  const ok = images.length > 0 && images.every(image => image.complete && image.naturalWidth > 0);
  document.body.dataset.rendered = ok ? 'yes' : 'no';
}
window.addEventListener('load', () => {
  markRendered();
  fit();
});
)";
}

}  // namespace raster::oracle
