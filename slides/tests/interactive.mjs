#!/usr/bin/env node
// interactive.mjs - drags every interactive figure in the built decks, in headless Chromium,
// and checks what it shows against Hitbox's geometry compiled natively.
//
//     node tests/interactive.mjs --dist dist --answers build/wasm/answers
//                                [--chromium /usr/bin/chromium] [--screenshots DIR] [--only NAME]
//
// For each figure: open its deck from disk (file://, as a lecturer would), drag its shapes
// with the mouse, read the answer the figure displays, and compare it with the same question
// put to `answers` (slides/wasm/answers.cpp: the same C++ built by g++). Some drags land on
// a case whose answer is known by hand (an edge touching, a time of impact worked out on
// paper): those check the geometry itself, not only that the two builds agree. Also: nothing
// is loaded from the network, and in print (the PDF) each figure is its still picture.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';

const options = { chromium: process.env.CHROME_PATH || '/usr/bin/chromium' };
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
if (!options.dist || !options.answers) {
  console.error('usage: interactive.mjs --dist DIR --answers PROGRAM [--chromium PATH] [--screenshots DIR] [--only NAME]');
  process.exit(2);
}

// The native answer to the question a figure asked (its function name and numbers).
function nativeAnswer([name, ...numbers]) {
  const line = execFileSync(options.answers, { input: `${name.replace(/Answer$/, '')} ${numbers.join(' ')}\n` });
  return String(line).trim().split(/\s+/).map(Number);
}
// Numbers as the figures print them: at most two decimals, a real minus sign.
const fmt = (value) => String(Number(value.toFixed(2))).replace('-', '\u2212');
const tick = (yes) => (yes ? '\u2713' : '\u2717');

// What each figure must show for a native answer `o` (figures.cpp gives each position).
const expected = {
  boxes: (o) => [0, 1, 2, 3].map((i) => tick(o[i])).concat(
    o[4] ? ['all four: overlap', `push A by (${fmt(o[5] * o[7])}, ${fmt(o[6] * o[7])})`] : ['one fails: apart']),
  pointInBox: (o) => [0, 1, 2, 3].map((i) => tick(o[i])).concat([o[4] ? 'inside: a hit' : 'outside: no hit']),
  circles: (o) => [`dy\u00b2 = ${fmt(o[0])}`, `\u00b2 = ${fmt(o[1])}`].concat(
    o[2] ? ['d\u00b2 < (rA + rB)\u00b2: hit', `depth ${fmt(o[5])}`] : ['d\u00b2 \u2265 (rA + rB)\u00b2: apart']),
  orientedBoxes: (o) => [o[0] ? 'a separating axis: apart' : 'every axis overlaps: hit', `axis (${fmt(o[1])}, ${fmt(o[2])})`,
    `shadow A ${fmt(o[20])} to ${fmt(o[21])}`, `shadow B ${fmt(o[22])} to ${fmt(o[23])}`,
    o[0] ? `gap ${fmt(o[3])}` : `least overlap ${fmt(-o[3])}`],
  ray: (o) => (o[0] ? ['the ray hits the box', `near t = ${fmt(o[1])}`,
    o[5] >= 0 ? `far t = ${fmt(o[5])} (leaves)` : 'far: after E']
    : o[6] ? ['the ray misses', `near t = ${fmt(o[7])} (enters)`, `far t = ${fmt(o[8])} (leaves)`]
      : ['the ray misses', 'x slab: ', 'y slab: ', 'no t inside both']),
  sweptBox: (o) => (!o[0] ? ['no hit this step'] : ['hits the wall this step',
    o[2] ? 'started inside: t = 0' : `time of impact t = ${fmt(o[1])}`, `normal (${fmt(o[3])}, ${fmt(o[4])})`]),
};

// Each figure: its deck, and drags [handle, dx, dy in the figure's pixels, text it must then
// show because the answer is known by hand (or null), and optionally arrow-key presses on
// that handle after the drag (1 pixel each: "ArrowRight" or ["ArrowDown", 2])].
const figures = [
  { name: 'boxes', deck: '01-bounding-volumes', drags: [
    ['a', -40, 0, 'one fails: apart'], // A.right 300 = B.left 300: touching is apart
    ['a', 0, 0, 'push A by (\u22121, 0)', 'ArrowRight'], // one pixel in: one pixel out
    ['a', 0, 0, 'one fails: apart', 'ArrowLeft'], // and back to touching
    ['a', 10, 0, 'push A by (\u221210, 0)'], // 10 pixels in: pushed 10 back out
    ['b', 200, 0, null], ['a', 0, 200, null]] },
  { name: 'pointInBox', deck: '01-bounding-volumes', drags: [
    ['p', 0, 0, 'outside: no hit'], // starts exactly on the left edge
    ['p', 10, 0, 'inside: a hit'], ['p', 310, 0, 'outside: no hit'], // x 520 = right edge
    ['p', -150, -150, null]] },
  { name: 'circles', deck: '01-bounding-volumes', drags: [
    ['a', 20, 100, 'apart'], // d = 210 = rA + rB: touching is apart
    ['a', 10, 0, 'depth 10'], ['b', -100, 50, null]] },
  { name: 'orientedBoxes', deck: '04-oriented-boxes', drags: [
    ['b', -60, 0, 'every axis overlaps: hit'], ['bTurn', 0, 120, null], ['a', 0, 100, null], ['aTurn', -80, 60, null]] },
  { name: 'ray', deck: '06-fast-objects', drags: [
    // S (60, 420) to E (160, 360): the line enters the box at x = 240, t = 1.8, after E, and
    // leaves at x = 460, t = 4: a miss that still shows near and far.
    ['e', -480, 280, 'near t = 1.8 (enters)'],
    ['e', 480, -280, null], // back to the start
    ['s', 0, 0, null], ['s', 300, -160, 'near t = 0 (starts inside)'], ['e', -200, 300, null], ['s', -200, 0, null],
    ['s', 0, -300, null]] }, // S above the box, the line beside it: the slabs' times shown
  { name: 'sweptBox', deck: '06-fast-objects', drags: [
    ['from', 0, 0, 'time of impact t = 0.62'], // (460 - 150) / 500
    ['to', -300, 0, 'no hit this step'], ['to', 200, 300, null], ['from', 300, 0, null],
    // A corner graze: from (210, 40) to (530, 20), size 90. The box's bottom-right corner
    // (300, 130) reaches x = 460 at t = 0.5, at y = 130 - 20 * 0.5 = 120: exactly the wall's
    // top-left corner, and rises past it. Touching is not a hit; with the end 1 pixel lower
    // the corner cuts 0.5 pixels in: a hit at t = 0.5.
    ['from', -150, -180, null], ['to', 70, -410, 'no hit this step'],
    ['to', 0, 0, 'time of impact t = 0.5', 'ArrowDown']] },
];

const browser = await chromium.launch({
  executablePath: options.chromium,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run'],
});
const problems = [];
let checks = 0;
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
  page.on('request', (request) => {
    if (!/^(file|data):/.test(request.url())) problems.push(`loads from the network: ${request.url()}`);
  });
  for (const figure of figures.filter((f) => !options.only || f.name === options.only)) {
    const url = `file://${path.resolve(options.dist, figure.deck)}.html`;
    await page.goto(url);
    await page.waitForFunction(() => document.documentElement.dataset.figuresReady === 'yes', null, { timeout: 15000 });
    const number = await page.evaluate((name) =>
      [...document.querySelectorAll('section[id]')].findIndex((s) => s.querySelector(`[data-figure="${name}"]`)) + 1, figure.name);
    if (number === 0) {
      problems.push(`${figure.name}: no slide in ${figure.deck}.html shows it`);
      continue;
    }
    await page.goto(`${url}#${number}`);
    await page.waitForTimeout(300);
    const root = page.locator(`.interactive[data-figure="${figure.name}"]`);
    for (const [handle, dx, dy, known, keys] of figure.drags) {
      const where = `${figure.name}: after dragging ${handle} by (${dx}, ${dy})${keys ? ` and ${keys}` : ''}`;
      const svg = await root.locator('.live svg').boundingBox();
      const scale = svg.width / 1160; // figure pixels to screen pixels
      const box = await root.locator(`[data-handle="${handle}"]`).boundingBox();
      const x = box.x + box.width / 2;
      const y = box.y + box.height / 2;
      await page.mouse.move(x, y);
      await page.mouse.down();
      await page.mouse.move(x + dx * scale, y + dy * scale, { steps: 8 });
      await page.mouse.up();
      if (keys) {
        const [key, times] = Array.isArray(keys) ? keys : [keys, 1];
        for (let i = 0; i < times; i++) await page.keyboard.press(key);
      }
      const shown = (await root.locator('.answer').allTextContents()).join('\n');
      const question = JSON.parse(await root.getAttribute('data-question'));
      const answer = nativeAnswer(question);
      for (const text of expected[figure.name](answer)) {
        checks += 1;
        if (!shown.includes(text)) problems.push(`${where}: shows\n${shown}\n  but the C++ answer to ${JSON.stringify(question)} means "${text}"`);
      }
      if (known !== null) {
        checks += 1;
        if (!shown.includes(known)) problems.push(`${where}: shows\n${shown}\n  but should show "${known}"`);
      }
    }
    if (options.screenshots) {
      fs.mkdirSync(options.screenshots, { recursive: true });
      await page.screenshot({ path: path.join(options.screenshots, `${figure.name}.png`) });
    }
    // In print (the PDF) the live figure gives way to its still picture.
    await page.emulateMedia({ media: 'print' });
    const print = await root.evaluate(async (element) => {
      const still = element.querySelector('img.still');
      await still.decode().catch(() => {});
      return { live: getComputedStyle(element.querySelector('.live')).display, still: still.naturalWidth };
    });
    await page.emulateMedia({ media: 'screen' });
    checks += 1;
    if (print.live !== 'none' || !(print.still > 0)) problems.push(`${figure.name}: in print, live ${print.live}, still ${print.still} px wide`);
  }
} finally {
  await browser.close();
}
if (problems.length > 0) {
  console.error(problems.join('\n'));
  console.error(`interactive figures: ${problems.length} problem(s)`);
  process.exit(1);
}
console.log(`interactive figures: ${options.only || figures.length} figures dragged in Chromium, ${checks} answers match the C++`);
