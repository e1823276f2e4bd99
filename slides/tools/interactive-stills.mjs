#!/usr/bin/env node
// interactive-stills.mjs - the still picture of each interactive figure, for the PDF.
//
//     node interactive-stills.mjs --wasm build/wasm/hitbox-geometry.js
//                                 --figures interactive/figures.js --out figures/generated
//
// Runs the figures' own drawing code (interactive/figures.js) with the geometry compiled to
// WebAssembly, on each figure's first state, and writes it as interactive-NAME.svg. A deck
// shows it with class="still": hidden on screen, printed in the PDF instead of the live figure.
import fs from 'node:fs';
import path from 'node:path';
import vm from 'node:vm';

const options = {};
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
if (!options.wasm || !options.figures || !options.out) {
  console.error('usage: interactive-stills.mjs --wasm FILE --figures FILE --out DIR');
  process.exit(2);
}
// Both files are plain browser scripts: run them as the page would, then use what they define.
vm.runInThisContext(fs.readFileSync(options.wasm, 'utf8'), { filename: options.wasm });
vm.runInThisContext(fs.readFileSync(options.figures, 'utf8'), { filename: options.figures });
const figures = globalThis.HitboxFigures;
figures.use(await globalThis.HitboxGeometry());
fs.mkdirSync(options.out, { recursive: true });
for (const [name, figure] of Object.entries(figures.figures)) {
  const file = path.join(options.out, `interactive-${name}.svg`);
  fs.writeFileSync(file, figures.render(name, figure.start).svg + '\n');
}
console.log(`interactive-stills: ${Object.keys(figures.figures).length} stills in ${options.out}`);
