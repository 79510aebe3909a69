// Runs an HTML map from seaway.webmap in jsdom (no network: jsdom loads no resources) and prints
// what Leaflet built: its version, the map's layers by kind, bound popups, layer-control rows,
// and any script error. Used by tests/test_webmap.py when node and jsdom are installed.
const fs = require('fs');
const { JSDOM, VirtualConsole } = require('jsdom');
const errors = [];
const vc = new VirtualConsole();
vc.on('jsdomError', e => errors.push(String(e.message || e)));
const dom = new JSDOM(fs.readFileSync(process.argv[2], 'utf8'), {
  runScripts: 'dangerously', pretendToBeVisual: true, virtualConsole: vc,
  // jsdom draws nothing: tell Leaflet that SVG works so that it builds its vector layers.
  beforeParse(win) { win.SVGSVGElement.prototype.createSVGRect = () => ({}); },
});
const w = dom.window;
setTimeout(() => {
  const map = w[Object.keys(w).find(k => k.startsWith('map_'))];
  const layers = {};
  let popups = 0;
  map.eachLayer(l => {
    const kind = l instanceof w.L.ImageOverlay ? 'image' : l instanceof w.L.CircleMarker ? 'circle'
      : l instanceof w.L.Polyline ? 'polyline' : l instanceof w.L.FeatureGroup ? 'group' : 'other';
    layers[kind] = (layers[kind] || 0) + 1;
    if (l.getPopup && l.getPopup()) popups++;
  });
  const controls = [...w.document.querySelectorAll('.leaflet-control-layers-overlays label')]
    .map(e => e.textContent.trim());
  console.log(JSON.stringify({ leaflet: w.L.version, errors, layers, popups, controls }));
}, 100);
