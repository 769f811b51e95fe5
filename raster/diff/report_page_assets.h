// The inline style sheet and script of the HTML diff report (image_diff_report.cpp writes the markup).
//
// The page must work opened from file:// on a machine without network, and be archived as it is by a CI
// system: everything is inline, no font, script or style is fetched. The script is progressive: without
// it every case shows side by side with its region boxes, its metrics and the status counts; with it come
// the filter, the slider and blink views, the zoom and the keyboard. Its state (view, zoom, slider
// position, blink, filter, current case) lives in the URL fragment, e.g.
// index.html#view=slider&pos=30&zoom=4&filter=failed,new, so that a link or a reload shows the same thing
// and a headless browser can open the page in a known state.
//
// The views follow what reviewers know from reg-cli and BackstopJS: side by side (expected, actual,
// diff), a slider that reveals the actual image over the expected one up to a handle that is dragged,
// and blink, which shows the two images in turn at an interval so that the eye catches what moves.
#pragma once

namespace curvescan::detail {

inline constexpr const char* kReportStyle = R"css(
:root{--zoom:1;--box:#ff00ff}
*{box-sizing:border-box}
body{font:14px/1.4 system-ui,sans-serif;margin:0;color:#222;background:#f4f4f4}
header{background:#fff;border-bottom:1px solid #ddd;padding:.6em 1.2em}
h1{font-size:1.3em;margin:.2em 0}
main{padding:.4em 1.2em 3em}
.options{color:#555;margin:.2em 0}
.filters,.toolbar{display:flex;flex-wrap:wrap;gap:.4em .8em;align-items:center;margin:.4em 0}
.chip{border-radius:3px;padding:.1em .5em;border:1px solid #ccc;cursor:pointer;user-select:none}
.chip b{font-variant-numeric:tabular-nums}
.s-failed,.s-error{background:#fdd}.s-size-mismatch{background:#fcd9b6}.s-new{background:#dde4ff}
.s-missing{background:#fff3c4}.s-passed{background:#dfd}
.keys{margin:.3em 0;color:#444}.keys table{border-collapse:collapse}
.keys td{padding:0 1em 0 0}kbd{font:12px monospace;border:1px solid #bbb;border-radius:3px;padding:0 .3em;background:#fafafa}
.case{background:#fff;border:1px solid #ddd;border-radius:4px;padding:.5em 1em;margin:.7em 0}
.case.current{border-color:#36c;box-shadow:0 0 0 2px #36c}
.case h2{margin:.1em 0;font-size:1em;font-family:monospace;font-weight:normal;word-break:break-all}
.case h2 a{color:inherit;text-decoration:none}
.badge{font:12px system-ui,sans-serif;padding:.05em .4em;border-radius:3px;margin-left:.6em}
.message{margin:.2em 0}
.case.compact{padding:.2em 1em;margin:.2em 0}.case.compact .message{color:#555;font-size:.9em}
details.metrics summary{cursor:pointer;color:#36c}
table.metrics{border-collapse:collapse;margin:.3em 0}table.metrics td{padding:0 .9em 0 0}
ol.regions{margin:.2em 0;padding-left:2em;font-family:monospace;font-size:.9em}
.views{margin:.4em 0}.views button.on{font-weight:bold;background:#dde4ff}
button{font:inherit;padding:.1em .6em}
figure{display:inline-block;margin:.3em 1em .3em 0;vertical-align:top}
figcaption{font-size:.85em;color:#555}
.frame{position:relative;display:inline-block;line-height:0;vertical-align:top;
background:repeating-conic-gradient(#e8e8e8 0% 25%,#fff 0% 50%) 0 0/16px 16px}
.frame img{display:block;image-rendering:pixelated}
.frame img.over{position:absolute;left:0;top:0}
.boxes{position:absolute;left:0;top:0;right:0;bottom:0;pointer-events:none}
.box{position:absolute;outline:2px solid var(--box);outline-offset:0}
body.no-regions .boxes{display:none}
.slider .handle{position:absolute;top:0;bottom:0;width:0;border-left:2px solid #36c;pointer-events:none}
.slider{cursor:ew-resize;touch-action:none}
.slider-label{display:block;margin:.3em 0}
.slider-range{width:min(30em,90%);vertical-align:middle}
.case[data-frame=expected] .blink img.over{visibility:hidden}
.blink{cursor:pointer}
.blink-state b{font-family:monospace}
.empty{color:#555;font-style:italic}
[hidden]{display:none!important}
)css";

// State: the URL fragment (see the file comment) is read once, then kept up to date with replaceState.
// Every case has data-view (side | slider | blink) and, in blink view, data-frame (expected | actual).
// <body> gets data-report-ready="1", data-images-loaded and data-images-broken once every image settled
// (the contract in image_diff.h), and data-script-error if the script failed.
inline constexpr const char* kReportScript = R"js(
(function () {
  'use strict';
  var body = document.body;
  window.addEventListener('error', function (e) { body.setAttribute('data-script-error', String(e.message)); });
  var views = ['side', 'slider', 'blink'];
  var zooms = [1, 2, 4, 8];
  var state = { view: 'side', zoom: 1, pos: 50, blink: 'on', frame: 'expected', interval: 500,
                regions: 'on', filter: null, current: -1 };
  var cases = Array.prototype.slice.call(document.querySelectorAll('article.case'));
  var viewCases = cases.filter(function (c) { return c.hasAttribute('data-views'); });
  var filterBoxes = Array.prototype.slice.call(document.querySelectorAll('.filters input[data-status]'));

  function readFragment() {
    var text = location.hash.replace(/^#/, '');
    if (text.indexOf('=') < 0) return;
    text.split('&').forEach(function (pair) {
      var eq = pair.indexOf('=');
      if (eq < 0) return;
      var key, value;
      try { key = decodeURIComponent(pair.slice(0, eq)); value = decodeURIComponent(pair.slice(eq + 1)); }
      catch (e) { return; }  // a malformed escape in a hand-edited link: that pair is ignored
      if (key === 'view' && views.indexOf(value) >= 0) state.view = value;
      else if (key === 'zoom' && zooms.indexOf(Number(value)) >= 0) state.zoom = Number(value);
      else if (key === 'pos' && isFinite(Number(value))) state.pos = Math.min(100, Math.max(0, Number(value)));
      else if (key === 'blink' && (value === 'on' || value === 'off')) state.blink = value;
      else if (key === 'frame' && (value === 'expected' || value === 'actual')) state.frame = value;
      else if (key === 'interval' && Number(value) >= 50 && Number(value) <= 10000) state.interval = Number(value);
      else if (key === 'regions' && (value === 'on' || value === 'off')) state.regions = value;
      else if (key === 'filter') state.filter = value === '' ? [] : value.split(',');
      else if (key === 'case' && /^[0-9]+$/.test(value)) state.current = Number(value);
    });
  }
  function writeFragment() {
    var parts = ['view=' + state.view, 'zoom=' + state.zoom, 'pos=' + state.pos, 'blink=' + state.blink,
                 'frame=' + state.frame, 'interval=' + state.interval, 'regions=' + state.regions,
                 'filter=' + enabledStatuses().join(',')];
    if (state.current >= 0) parts.push('case=' + state.current);
    try { history.replaceState(null, '', '#' + parts.join('&')); } catch (e) { /* some file:// policies refuse */ }
  }

  function enabledStatuses() {
    return filterBoxes.filter(function (b) { return b.checked; }).map(function (b) { return b.dataset.status; });
  }
  function applyFilter() {
    var enabled = enabledStatuses(), shown = 0;
    cases.forEach(function (c) {
      c.hidden = enabled.indexOf(c.dataset.status) < 0;
      if (!c.hidden) shown++;
    });
    var empty = document.getElementById('empty');
    if (empty) empty.hidden = shown > 0;
    body.setAttribute('data-shown-cases', String(shown));
  }

  function setSlider(entry, pos) {
    pos = Math.min(100, Math.max(0, Math.round(pos)));
    state.pos = pos;  // the fragment keeps the last position set
    entry.dataset.pos = String(pos);
    var over = entry.querySelector('.slider img.over'), handle = entry.querySelector('.slider .handle');
    var range = entry.querySelector('.slider-range');
    if (over) over.style.clipPath = 'inset(0 ' + (100 - pos) + '% 0 0)';
    if (handle) handle.style.left = pos + '%';
    if (range && Number(range.value) !== pos) range.value = String(pos);
  }
  function setView(entry, view) {
    entry.dataset.view = view;
    entry.querySelectorAll('.view').forEach(function (v) { v.hidden = v.dataset.view !== view; });
    entry.querySelectorAll('.views button').forEach(function (b) { b.classList.toggle('on', b.dataset.view === view); });
  }
  function setFrame(frame) {
    state.frame = frame;
    viewCases.forEach(function (c) { c.dataset.frame = frame; });
    document.querySelectorAll('.blink-state b').forEach(function (b) { b.textContent = frame; });
  }
  function setAllViews(view) {
    state.view = view;
    viewCases.forEach(function (c) { setView(c, view); });
    document.querySelectorAll('.toolbar button[data-view]').forEach(function (b) {
      b.classList.toggle('on', b.dataset.view === view);
    });
  }
  function setZoom(zoom) {
    state.zoom = zoom;
    var select = document.getElementById('zoom');
    if (select) select.value = String(zoom);
    Array.prototype.forEach.call(document.images, sizeImage);
  }
  function sizeImage(img) {
    if (img.naturalWidth > 0) {
      img.style.width = (img.naturalWidth * state.zoom) + 'px';
      img.style.height = (img.naturalHeight * state.zoom) + 'px';
    }
  }
  function setRegions(on) {
    state.regions = on ? 'on' : 'off';
    body.classList.toggle('no-regions', !on);
    var box = document.getElementById('show-regions');
    if (box) box.checked = on;
  }

  var timer = null;
  function setBlink(on) {
    state.blink = on ? 'on' : 'off';
    if (timer !== null) { clearInterval(timer); timer = null; }
    if (on) timer = setInterval(function () { setFrame(state.frame === 'expected' ? 'actual' : 'expected'); }, state.interval);
    var button = document.getElementById('blink-toggle');
    if (button) button.textContent = on ? 'pause blinking (b)' : 'resume blinking (b)';
    body.setAttribute('data-blinking', state.blink);
  }

  function visibleCases() { return cases.filter(function (c) { return !c.hidden; }); }
  function setCurrent(entry, scroll) {
    cases.forEach(function (c) { c.classList.toggle('current', c === entry); });
    state.current = entry ? cases.indexOf(entry) : -1;
    if (entry && scroll) { entry.focus({ preventScroll: true }); entry.scrollIntoView({ block: 'start' }); }
  }
  function moveCurrent(step) {
    var shown = visibleCases();
    if (shown.length === 0) return;
    var at = shown.indexOf(cases[state.current]);
    var next = at < 0 ? (step > 0 ? 0 : shown.length - 1) : Math.min(shown.length - 1, Math.max(0, at + step));
    setCurrent(shown[next], true);
  }

  // Wiring.
  viewCases.forEach(function (entry) {
    entry.querySelectorAll('.views button').forEach(function (button) {
      button.addEventListener('click', function () { setView(entry, button.dataset.view); });
    });
    var range = entry.querySelector('.slider-range');
    if (range) {
      range.addEventListener('input', function () { setSlider(entry, Number(range.value)); });
      range.addEventListener('change', writeFragment);
    }
    var frame = entry.querySelector('.frame.slider');
    if (frame) {
      var dragging = false;
      var follow = function (e) {
        var rect = frame.getBoundingClientRect();
        if (rect.width > 0) setSlider(entry, 100 * (e.clientX - rect.left) / rect.width);
      };
      frame.addEventListener('pointerdown', function (e) {
        dragging = true;
        try { frame.setPointerCapture(e.pointerId); } catch (err) { /* a synthetic pointer has no capture */ }
        follow(e); e.preventDefault();
      });
      frame.addEventListener('pointermove', function (e) { if (dragging) follow(e); });
      frame.addEventListener('pointerup', function () { if (dragging) writeFragment(); dragging = false; });
      frame.addEventListener('pointercancel', function () { dragging = false; });
    }
    var blinkFrame = entry.querySelector('.frame.blink');
    if (blinkFrame) {
      blinkFrame.addEventListener('click', function () {
        setBlink(false); setFrame(state.frame === 'expected' ? 'actual' : 'expected'); writeFragment();
      });
    }
  });
  cases.forEach(function (entry) {
    entry.addEventListener('click', function () { setCurrent(entry, false); writeFragment(); });
  });
  filterBoxes.forEach(function (b) { b.addEventListener('change', function () { applyFilter(); writeFragment(); }); });
  document.querySelectorAll('.toolbar button[data-view]').forEach(function (b) {
    b.addEventListener('click', function () { setAllViews(b.dataset.view); writeFragment(); });
  });
  var zoomSelect = document.getElementById('zoom');
  if (zoomSelect) zoomSelect.addEventListener('change', function () { setZoom(Number(zoomSelect.value)); writeFragment(); });
  var intervalSelect = document.getElementById('interval');
  if (intervalSelect) {
    intervalSelect.addEventListener('change', function () {
      state.interval = Number(intervalSelect.value); setBlink(state.blink === 'on'); writeFragment();
    });
  }
  var blinkButton = document.getElementById('blink-toggle');
  if (blinkButton) blinkButton.addEventListener('click', function () { setBlink(state.blink !== 'on'); writeFragment(); });
  var regionsBox = document.getElementById('show-regions');
  if (regionsBox) regionsBox.addEventListener('change', function () { setRegions(regionsBox.checked); writeFragment(); });

  document.addEventListener('keydown', function (e) {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    var target = e.target;
    if (target && (target.tagName === 'INPUT' && target.type !== 'checkbox' && target.type !== 'range' ||
                   target.tagName === 'SELECT' || target.tagName === 'TEXTAREA')) return;
    var current = cases[state.current];
    var handled = true;
    switch (e.key) {
      case 'j': case 'n': moveCurrent(1); break;
      case 'k': case 'p': moveCurrent(-1); break;
      case '1': setAllViews('side'); break;
      case '2': setAllViews('slider'); break;
      case '3': setAllViews('blink'); break;
      case 'b': setBlink(state.blink !== 'on'); break;
      case 't': setBlink(false); setFrame(state.frame === 'expected' ? 'actual' : 'expected'); break;
      case 'r': setRegions(state.regions !== 'on'); break;
      case '+': case '=': setZoom(zooms[Math.min(zooms.length - 1, zooms.indexOf(state.zoom) + 1)]); break;
      case '-': setZoom(zooms[Math.max(0, zooms.indexOf(state.zoom) - 1)]); break;
      case 'ArrowLeft': case 'ArrowRight':
        if (!current || current.dataset.view !== 'slider' || (target && target.type === 'range')) { handled = false; break; }
        setSlider(current, Number(current.dataset.pos || 50) + (e.key === 'ArrowLeft' ? -5 : 5));
        break;
      default: handled = false;
    }
    if (handled) { e.preventDefault(); writeFragment(); }
  });

  // Initial state: the fragment, else the defaults (every status shown).
  readFragment();
  if (state.filter !== null) filterBoxes.forEach(function (b) { b.checked = state.filter.indexOf(b.dataset.status) >= 0; });
  applyFilter();
  setAllViews(state.view);
  viewCases.forEach(function (c) { setSlider(c, state.pos); });
  setFrame(state.frame);
  setRegions(state.regions === 'on');
  if (intervalSelect) {
    // An interval from the link that the list lacks is added to it, so that the list shows what runs.
    if (!Array.prototype.some.call(intervalSelect.options, function (o) { return Number(o.value) === state.interval; })) {
      var option = document.createElement('option');
      option.value = String(state.interval);
      option.textContent = state.interval + ' ms';
      intervalSelect.appendChild(option);
    }
    intervalSelect.value = String(state.interval);
  }
  setZoom(state.zoom);
  setBlink(state.blink === 'on');
  if (state.current >= 0 && state.current < cases.length) setCurrent(cases[state.current], true);

  var images = Array.prototype.slice.call(document.images);
  var pending = images.length, loaded = 0, broken = 0;
  function done() {
    body.setAttribute('data-images-loaded', String(loaded));
    body.setAttribute('data-images-broken', String(broken));
    body.setAttribute('data-report-ready', '1');
  }
  function settle(img) {
    if (img.naturalWidth > 0) { loaded++; sizeImage(img); } else { broken++; }
    if (--pending === 0) done();
  }
  images.forEach(function (img) {
    if (img.complete) { settle(img); return; }
    var once = function () {
      img.removeEventListener('load', once); img.removeEventListener('error', once); settle(img);
    };
    img.addEventListener('load', once);
    img.addEventListener('error', once);
  });
  if (images.length === 0) done();
})();
)js";

}  // namespace curvescan::detail
