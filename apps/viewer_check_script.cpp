// The viewer page's oracle check (viewer_check_script.h).
#include "apps/viewer_check_script.h"

namespace raster::cli {

const char* viewer_check_script() {
    return R"SCRIPT(// The last check: its result (GET /check), the parameters of the frame it judged, the hash of its map's bytes.
const check = {result: null, params: null, mapHash: null};

// The check's result as text: the verdict, the genuine counts by reason, the ambiguous ones by class, the times.
function checkText(result) {
  const c = result.comparison;
  const ambiguous = Object.entries(c.ambiguous).filter(([, n]) => n > 0).map(([name, n]) => `${name.replace('_', ' ')} ${n}`);
  const samples = c.width * c.height * c.samples;
  return `${result.verdict === 'pass' ? 'PASS' : 'FAIL'}: genuine ${c.genuine_total}` +
         (c.genuine_total > 0 ? ` (${c.genuine_reasons})` : '') +
         `, ambiguous ${c.ambiguous_total}` + (ambiguous.length ? ` (${ambiguous.join(', ')})` : '') +
         ` of ${samples} samples; oracle ${c.oracle_ms.toFixed(0)} ms, comparison ${c.compare_ms.toFixed(0)} ms`;
}

function showLegend(legend) {
  const box = $('check-legend');
  box.textContent = '';
  for (const {colour, meaning} of legend) {
    const line = document.createElement('div'), swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = colour;
    swatch.dataset.colour = colour;
    line.append(swatch, meaning);
    box.appendChild(line);
  }
}

// The view changed since the check: its map no longer lies over the frame shown.
function checkIsStale() {
  $('overlay').hidden = true;
  $('check-result').dataset.stale = 'yes';
  $('check-result').textContent = 'The frame has changed since the last check: press check again. (' +
                                  checkText(check.result) + ', for the earlier frame.)';
}

// Asks the server to check the current view's frame against the oracle, then lays its map over the frame.
async function runCheck() {
  const params = renderParams();
  $('check-run').disabled = true;
  $('check-result').textContent = 'checking: rendering the frame again and casting the oracle\'s rays...';
  try {
    const response = await fetch('/check?' + new URLSearchParams(params), {cache: 'no-store'});
    if (!response.ok) {
      $('check-result').textContent = `the server refused the check (${response.status}): ${await response.text()}`;
      return null;
    }
    const result = await response.json();
    const map = await fetch(result.map, {cache: 'no-store'});
    if (!map.ok) throw new Error(`the map could not be fetched (${map.status}): ${await map.text()}`);
    const bytes = new Uint8Array(await map.arrayBuffer());
    await showPng($('overlay'), bytes);
    Object.assign(check, {result, params: JSON.stringify(params), mapHash: selftest ? fnv1a64(bytes) : null});
    $('check-result').dataset.stale = 'no';
    $('check-result').dataset.verdict = result.verdict;
    $('check-result').textContent = checkText(result);
    showLegend(result.legend);
    $('check-overlay').disabled = false;
    $('overlay').hidden = !$('check-overlay').checked || check.params !== JSON.stringify(renderParams());
    return result;
  } catch (error) {
    if (error instanceof TypeError) serverGone(error);
    else $('check-result').textContent = `the check failed: ${error}`;
    return null;
  } finally {
    $('check-run').disabled = false;
  }
}
)SCRIPT";
}

}  // namespace raster::cli
