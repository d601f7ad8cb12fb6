// The viewer page's self-test script: clicks, drags, the wheel, the time slider, play, a camera pick, the shadow
// and transparency switches, the sample count, MSAA, the filter, the camera reset and the oracle check, checked.
#include "apps/viewer_self_test.h"

namespace raster::cli {

const char* viewer_self_test_script() {
    return R"SCRIPT(// The self-test's animation steps: the slider moved to the middle of the keys, then play pressed until three
// frames have come, then pause; checks that each asked for its instant and that the instants moved on.
async function animationSelfTest(report, step, before) {
  const {start, end} = scene.animation;
  const middle = (start + end) / 2;
  const scrubbed = await step('time slider', () => {
    $('time').value = String(middle);
    $('time').dispatchEvent(new Event('input', {bubbles: true}));
  });
  const played = [];
  await new Promise((resolve) => {
    const seen = frames.length;
    $('play').dispatchEvent(new MouseEvent('click', {bubbles: true, cancelable: true, view: window}));
    const poll = () => {
      if (frames.length - seen >= 3) {
        $('play').dispatchEvent(new MouseEvent('click', {bubbles: true, cancelable: true, view: window}));
        played.push(...frames.slice(seen));
        resolve();
      } else {
        setTimeout(poll, 10);
      }
    };
    poll();
  });
  await idle();
  report.steps.push({name: 'play', new_frames: played.length, frame: frames[frames.length - 1]});
  const times = played.map((frame) => Number(frame.params.time));
  report.checks = {
    slider_asked_for_its_instant: Math.abs(Number(scrubbed.params.time) - middle) < 0.01,
    slider_changed_the_image: scrubbed.hash !== before.hash,
    play_advanced_the_instant: times.length >= 3 && times.every((t, i) => i === 0 || t !== times[i - 1]),
    pause_stopped_playing: !playing && $('play').getAttribute('aria-pressed') === 'false',
  };
}

// The self-test's steps through the remaining controls: another sample count, MSAA, a texture filter (a textured
// scene) and the camera reset, each checked to ask for its frame; the sample count and the reset (from an orbited
// view) to change it.
async function controlsSelfTest(report, step) {
  const click = (id) => () => $(id).dispatchEvent(new MouseEvent('click', {bubbles: true, cancelable: true, view: window}));
  const beforeSamples = frames[frames.length - 1];
  const samples = view.samples === 4 ? 16 : 4;
  const sampled = await step('samples ' + samples, click(`samples-${samples}`));
  const msaaWas = view.msaa;
  const msaa = await step('msaa', () => $('msaa').click());  // a checkbox: the click toggles it and fires change
  const checks = {
    samples_asked_for: sampled.params.samples === String(samples),
    samples_changed_the_image: sampled.hash !== beforeSamples.hash,
    msaa_asked_for: msaa.params.msaa === (msaaWas ? '0' : '1') && $('msaa').checked === !msaaWas,
  };
  if (scene.textured) {
    const filter = FILTERS.find((f) => f !== (view.filter || scene.filter));
    const filtered = await step('filter ' + filter, click(`filter-${filter}`));
    checks.filter_asked_for = filtered.params.filter === filter &&
                              $(`filter-${filter}`).getAttribute('aria-pressed') === 'true';
  }
  const beforeReset = frames[frames.length - 1];
  const reset = await step('camera reset', click('camera-reset'));
  const atHome = (params) => params.yaw === '0.00' && params.pitch === '0.00' && params.distance === '1.0000';
  checks.reset_asked_for = atHome(reset.params);
  // Picking a camera already resets the orbit: then the reset has nothing to change.
  checks.reset_changed_the_image = atHome(beforeReset.params) ? reset.hash === beforeReset.hash
                                                              : reset.hash !== beforeReset.hash;
  report.checks = {...report.checks, ...checks};
}

// The self-test's check steps: the check button pressed on the frame shown, its map laid over that frame (the bytes
// the server made, at the frame's size), the counts shown, the overlay toggled off and on, then a shading change
// that must hide the map of the earlier frame.
async function checkSelfTest(report) {
  const onScreen = frames[frames.length - 1];
  $('check-run').dispatchEvent(new MouseEvent('click', {bubbles: true, cancelable: true, view: window}));
  // The click starts the check; wait until the button is enabled again (the check has ended).
  await new Promise((resolve) => {
    const poll = () => ($('check-run').disabled || !check.result ? setTimeout(poll, 10) : resolve());
    setTimeout(poll, 0);
  });
  const result = check.result, overlay = $('overlay');
  const shownText = $('check-result').textContent;
  const [over, under] = [overlay.getBoundingClientRect(), image.getBoundingClientRect()];
  const overlayShown = !overlay.hidden && overlay.naturalWidth === image.naturalWidth &&
                       overlay.naturalHeight === image.naturalHeight && over.left === under.left &&
                       over.top === under.top && over.width === under.width && over.height === under.height;
  $('check-overlay').click();
  const toggledOff = overlay.hidden;
  $('check-overlay').click();
  const toggledOn = !overlay.hidden;
  const other = view.shading === 'gouraud' ? 'phong' : 'gouraud';
  $(`shading-${other}`).dispatchEvent(new MouseEvent('click', {bubbles: true, cancelable: true, view: window}));
  await idle();
  report.check = {index: result.index, verdict: result.verdict, frame_index: onScreen.index,
                  frame_png_fnv1a64: result.frame_png_fnv1a64, map_png_fnv1a64: result.map_png_fnv1a64,
                  map_shown_fnv1a64: check.mapHash, text: shownText, genuine_total: result.comparison.genuine_total,
                  ambiguous_total: result.comparison.ambiguous_total};
  report.checks = {
    ...report.checks,
    check_judged_the_frame_on_screen: result.frame_png_fnv1a64 === onScreen.hash,
    check_overlay_is_the_servers_map: check.mapHash === result.map_png_fnv1a64,
    check_overlay_lies_over_the_frame: overlayShown,
    check_counts_shown: shownText.startsWith(result.verdict === 'pass' ? 'PASS' : 'FAIL') &&
                        shownText.includes(`ambiguous ${result.comparison.ambiguous_total}`),
    check_legend_shown: document.querySelectorAll('#check-legend .swatch').length === result.legend.length,
    check_overlay_toggles: toggledOff && toggledOn,
    check_hidden_once_the_view_moves: overlay.hidden && $('check-result').dataset.stale === 'yes',
  };
}

// The self-test (?selftest=1): a user's click, drag and wheel, as DOM events through the handlers above, each
// followed by the frame it brought; the report says what each frame asked for and the hash of the bytes shown.
async function runSelfTest() {
  const report = {steps: []};
  try {
    await idle();
    const step = async (name, act) => {
      const before = frames.length;
      act();
      await idle();
      const frame = frames[frames.length - 1];
      report.steps.push({name, new_frames: frames.length - before, frame});
      return frame;
    };
    const first = await step('initial', () => {});
    const flat = await step('click shading-flat', () =>
      $('shading-flat').dispatchEvent(new MouseEvent('click', {bubbles: true, cancelable: true, view: window})));
    const box = image.getBoundingClientRect();
    const centre = {clientX: box.left + box.width / 2, clientY: box.top + box.height / 2};
    const pointer = (type, dx, dy) => image.dispatchEvent(new PointerEvent(type, {
      bubbles: true, cancelable: true, pointerId: 1, pointerType: 'mouse', isPrimary: true, button: 0,
      buttons: type === 'pointerup' ? 0 : 1, clientX: centre.clientX + dx, clientY: centre.clientY + dy}));
    const dragged = await step('drag', () => {
      pointer('pointerdown', 0, 0);
      pointer('pointermove', 60, 25);
      pointer('pointerup', 60, 25);
    });
    const zoomed = await step('wheel', () => image.dispatchEvent(new WheelEvent('wheel', {
      bubbles: true, cancelable: true, deltaY: 300, ...centre})));
    if (scene.animation) await animationSelfTest(report, step, zoomed);
    // Transparency first: a transparent surface casts no shadow, so with everything opaque the shadow switch shows.
    if (scene.blended) {
      const before = frames[frames.length - 1];
      const opaque = await step('transparency opaque', () => $('transparency-opaque').dispatchEvent(
        new MouseEvent('click', {bubbles: true, cancelable: true, view: window})));
      report.checks = {...report.checks, opaque_asked_for: opaque.params.transparency === 'opaque',
                       opaque_changed_the_image: opaque.hash !== before.hash};
    }
    if (scene.canCastShadows) {
      const other = scene.shadows ? 'off' : 'on';
      const before = frames[frames.length - 1];
      const switched = await step('shadows ' + other, () => $(`shadows-${other}`).dispatchEvent(
        new MouseEvent('click', {bubbles: true, cancelable: true, view: window})));
      report.checks = {...report.checks, shadows_asked_for: switched.params.shadows === other,
                       shadows_changed_the_image: switched.hash !== before.hash};
    }
    if (scene.cameras.length > 1) {
      const other = scene.loadedCamera === 0 ? 1 : 0;
      const before = frames[frames.length - 1];
      const picked = await step('pick a camera', () => $(`camera-pick-${other}`).dispatchEvent(
        new MouseEvent('click', {bubbles: true, cancelable: true, view: window})));
      report.checks = {...report.checks, camera_asked_for: picked.params.camera === String(other),
                       camera_changed_the_image: picked.hash !== before.hash};
    }
    await controlsSelfTest(report, step);
    await checkSelfTest(report);
    report.checks = {
      ...report.checks,
      flat_asked_for: flat.params.shading === 'flat',
      flat_changed_the_image: flat.hash !== first.hash,
      drag_moved_the_camera: flat.params.yaw !== dragged.params.yaw && flat.params.pitch !== dragged.params.pitch,
      drag_changed_the_image: dragged.hash !== flat.hash,
      drag_kept_the_shading: dragged.params.shading === 'flat',
      wheel_moved_the_camera_back: Number(zoomed.params.distance) > Number(dragged.params.distance),
      wheel_changed_the_image: zoomed.hash !== dragged.hash,
    };
    report.pass = Object.values(report.checks).every(Boolean);
  } catch (error) {
    report.error = String(error);
    report.pass = false;
  }
  $('selftest').textContent = JSON.stringify(report);
  $('selftest').hidden = false;
  document.body.dataset.selftest = report.pass ? 'pass' : 'fail';
}
)SCRIPT";
}

}  // namespace raster::cli
