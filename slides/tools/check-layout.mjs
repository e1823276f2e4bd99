#!/usr/bin/env node
// check-layout.mjs - every slide's content fits on the slide, measured in a real browser.
//
//     node check-layout.mjs --dist dist [--chromium /usr/bin/chromium]
//
// Opens every deck's HTML in headless Chromium (Debian's chromium, driven by
// playwright-core) and, on every slide, measures each element against the slide: a
// heading, paragraph, list, table, code block or picture whose bottom lies below the
// slide's bottom padding (where the footer and page number sit) is cut off on the screen
// and in the PDF. The text check-decks.mjs does on the Markdown cannot see this: a formula
// under 16 lines of code, a long bullet list, a picture too tall.
// It also measures every diagram label as shown: a <text> in an SVG picture (an <img> of an
// .svg, or an SVG drawn in the slide) smaller than 24 slide pixels fails (body text is 30 px;
// a label the back row cannot read shows nothing). The size on the slide is the label's font
// size times the scale the picture is drawn at (its width on the slide over its viewBox).
// The same holds for the screenshots the programs draw (figures/generated/*.png, *.apng): their
// smallest text, in the picture's own pixels, is in figures/generated/figure-text.json
// (make-figures.py writes it from figures.txt's text=PX), times the scale the picture is drawn
// at; a screenshot whose text size is not known (a lab's whole screenshot.png, whose help line
// is small) fails too. And a screenshot keeps a margin from the slide's edge (`margin`, 16 px): a
// dark picture flush against the edge of the projected slide reads as cut off.
// In print, each interactive figure's still (the PDF's picture of it) must show its whole
// frame: the outermost pixels of each of its four sides, as Chromium draws it on the slide,
// are mostly the border's grey (a border drawn on the picture's edge is half outside it, and
// the answer panel's white covered the right side).
// Without Chromium the check says so and passes (the build itself needs no browser).
import fs from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';

const options = { chromium: process.env.CHROME_PATH || '/usr/bin/chromium' };
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
if (!options.dist) {
  console.error('usage: check-layout.mjs --dist DIR [--chromium PATH]');
  process.exit(2);
}
if (!fs.existsSync(options.chromium)) {
  console.log(`check-layout: skipped, no Chromium at ${options.chromium} (apt-get install chromium)`);
  process.exit(0);
}

const browser = await chromium.launch({
  executablePath: options.chromium,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run'],
});
const problems = [];
let slides = 0;
// The smallest label a diagram may have, in slide pixels (1280x720 slides).
const minimumLabel = Number(process.env.HITBOX_MIN_LABEL || 24);
const margin = 16;
const textSizesFile = path.resolve(options.dist, 'figures', 'generated', 'figure-text.json');
const textSizes = fs.existsSync(textSizesFile) ? JSON.parse(fs.readFileSync(textSizesFile, 'utf8')) : {};
// The labels of one SVG file: viewBox size and each <text>'s font size in its own units.
const svgLabels = new Map();
async function labelsOf(page, file) {
  if (!svgLabels.has(file)) {
    await page.goto(`file://${file}`);
    svgLabels.set(file, await page.evaluate(() => {
      const root = document.documentElement;
      const box = root.viewBox && root.viewBox.baseVal;
      const width = box && box.width ? box.width : parseFloat(root.getAttribute('width'));
      const height = box && box.height ? box.height : parseFloat(root.getAttribute('height'));
      const texts = [...root.querySelectorAll('text')].filter((t) => t.textContent.trim() !== '');
      return { width, height, texts: texts.map((t) => ({ size: parseFloat(getComputedStyle(t).fontSize), text: t.textContent.trim().slice(0, 40) })) };
    }));
  }
  return svgLabels.get(file);
}
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  const decks = fs.readdirSync(options.dist).filter((f) => /^\d\d-.*\.html$/.test(f)).sort();
  // On screen (the HTML) and in print (the PDF: animations and interactive figures show
  // their stills there).
  for (const media of ['screen', 'print']) for (const deck of decks) {
    await page.emulateMedia({ media });
    await page.goto(`file://${path.resolve(options.dist, deck)}`);
    await page.waitForLoadState('load');
    const found = await page.evaluate(() => {
      const result = [];
      const sections = [...document.querySelectorAll('section[id]')];
      sections.forEach((section, index) => {
        const box = section.getBoundingClientRect();
        if (box.height === 0) return;
        // Measured in the slide's own pixels (the page may scale the 1280x720 slide).
        const scale = box.height / section.offsetHeight;
        const bottom = box.top + (section.offsetHeight - parseFloat(getComputedStyle(section).paddingBottom) + 6) * scale;
        for (const element of section.querySelectorAll('h1, h2, p, li, pre, table, img, svg, mjx-container')) {
          const own = element.getBoundingClientRect();
          if (own.height === 0 || element.closest('header, footer')) continue;
          if (getComputedStyle(element).display === 'none') continue;
          if (element.matches('img') && section.getAttribute('data-class')?.includes('bg')) continue;
          if (own.bottom > bottom) {
            const text = (element.textContent || element.getAttribute('src') || element.tagName).trim().slice(0, 50);
            result.push(`slide ${index + 1}: ${element.tagName.toLowerCase()} "${text}" ends ${Math.round((own.bottom - bottom) / scale)} px below the slide's content area`);
            break;
          }
        }
      });
      // Diagram labels: SVG pictures (measured in node from the file) and SVG in the slide.
      const images = [];
      const inline = [];
      const rasters = []; // screenshots: where each is drawn, in slide pixels
      const raster = /figures\/(?:generated|labs)\/[^/"')]+\.a?png$/i;
      sections.forEach((section, index) => {
        const box = section.getBoundingClientRect();
        if (box.height === 0) return;
        const scale = box.height / section.offsetHeight;
        // An <img> fills its box, unless it is fitted into it (object-fit: contain).
        const place = (src, own, fit) => rasters.push({ slide: index + 1, src: src.replace(/^.*\/(figures\/)/, '$1'),
          left: (own.left - box.left) / scale, top: (own.top - box.top) / scale,
          width: own.width / scale, height: own.height / scale, fit });
        for (const picture of section.querySelectorAll('img, svg image')) {
          const src = picture.getAttribute('src') || picture.getAttribute('href') || '';
          const own = picture.getBoundingClientRect();
          if (raster.test(src) && own.width > 0 && getComputedStyle(picture).display !== 'none' &&
              !(picture.closest('svg') && getComputedStyle(picture.closest('svg')).display === 'none'))
            place(src, own, getComputedStyle(picture).objectFit === 'contain');
        }
        for (const img of section.querySelectorAll('img')) {
          const src = img.getAttribute('src') || '';
          const own = img.getBoundingClientRect();
          if (!/\.svg$/i.test(src) || own.width === 0 || getComputedStyle(img).display === 'none') continue;
          images.push({ slide: index + 1, src, width: own.width / scale, height: own.height / scale });
        }
        for (const text of section.querySelectorAll('svg text')) {
          if (text.textContent.trim() === '' || text.closest('header, footer, mjx-container')) continue;
          const own = text.getBoundingClientRect();
          if (own.width === 0) continue;
          const matrix = text.getScreenCTM();
          const size = parseFloat(getComputedStyle(text).fontSize) * Math.hypot(matrix.a, matrix.b) / scale;
          inline.push({ slide: index + 1, size, text: text.textContent.trim().slice(0, 40) });
        }
      });
      // Marp's split backgrounds (![bg right:40% fit](x.svg)): a <figure> with the SVG as its
      // background image, drawn to fit ("contain") the figure's box.
      const slideFrames = [...document.querySelectorAll('svg[data-marpit-svg]')];
      for (const figure of document.querySelectorAll('section[data-marpit-advanced-background="background"] figure')) {
        const style = getComputedStyle(figure);
        const url = /url\("?([^")]*\.svg)"?\)/i.exec(figure.style.backgroundImage || '');
        const section = figure.closest('section');
        const box = section.getBoundingClientRect();
        const own = figure.getBoundingClientRect();
        if (!url || own.width === 0 || box.height === 0 || style.display === 'none') continue;
        const scale = box.height / section.offsetHeight;
        const slide = slideFrames.indexOf(figure.closest('svg[data-marpit-svg]')) + 1;
        images.push({ slide, src: url[1].replace(/^.*\/(figures\/)/, '$1'), width: own.width / scale, height: own.height / scale });
      }
      // Split backgrounds of screenshots: the box they are fitted ("contain") into.
      for (const figure of document.querySelectorAll('section[data-marpit-advanced-background="background"] figure')) {
        const style = getComputedStyle(figure);
        const url = /url\("?([^")]*\.a?png)"?\)/i.exec(figure.style.backgroundImage || '');
        const frame = figure.closest('svg[data-marpit-svg]');
        const section = frame && frame.querySelector('section:not([data-marpit-advanced-background])') || figure.closest('section');
        const box = section.getBoundingClientRect();
        const own = figure.getBoundingClientRect();
        if (!url || !raster.test(url[1]) || own.width === 0 || box.height === 0 || style.display === 'none') continue;
        const scale = box.height / section.offsetHeight;
        const inset = style.backgroundOrigin === 'content-box' ? ['Left', 'Top', 'Right', 'Bottom'].map((side) => parseFloat(style['padding' + side]) * scale) : [0, 0, 0, 0];
        rasters.push({ slide: slideFrames.indexOf(frame) + 1, src: url[1].replace(/^.*\/(figures\/)/, '$1'), fit: true,
          left: (own.left + inset[0] - box.left) / scale, top: (own.top + inset[1] - box.top) / scale,
          width: (own.width - inset[0] - inset[2]) / scale, height: (own.height - inset[1] - inset[3]) / scale });
      }
      return { result, count: sections.length, images, inline, rasters };
    });
    if (media === 'screen') {
      slides += found.count;
      for (const problem of found.result) problems.push(`${deck} ${problem}`);
    }
    // Before the labels below: measuring an SVG's labels opens that file in this page.
    if (media === 'print') {
      const stills = page.locator('section .interactive img.still');
      for (let i = 0; i < await stills.count(); i++) {
        const still = stills.nth(i);
        const shot = await still.screenshot().catch(() => null);
        if (!shot) continue;
        const where = await still.evaluate((img) => {
          const frames = [...document.querySelectorAll('svg[data-marpit-svg]')];
          return { slide: frames.indexOf(img.closest('svg[data-marpit-svg]')) + 1, src: img.getAttribute('src') };
        });
        const missing = await page.evaluate(async (png) => {
          const img = new Image();
          img.src = `data:image/png;base64,${png}`;
          await img.decode();
          const canvas = document.createElement('canvas');
          [canvas.width, canvas.height] = [img.width, img.height];
          const context = canvas.getContext('2d');
          context.drawImage(img, 0, 0);
          // A side is there when, in its outermost 2 pixels, 90 % of the places along it
          // have a pixel darker than light grey.
          const data = context.getImageData(0, 0, canvas.width, canvas.height).data;
          const dark = (x, y) => { const at = 4 * (y * canvas.width + x); return data[at] + data[at + 1] + data[at + 2] < 3 * 200; };
          const side = (along, at) => {
            let found = 0;
            for (let i = 4; i < along - 4; i++) if (at(i, 0) || at(i, 1)) found++;
            return found >= 0.9 * (along - 8);
          };
          const { width: w, height: h } = canvas;
          const sides = { top: side(w, (i, d) => dark(i, d)), bottom: side(w, (i, d) => dark(i, h - 1 - d)),
            left: side(h, (i, d) => dark(d, i)), right: side(h, (i, d) => dark(w - 1 - d, i)) };
          return Object.keys(sides).filter((name) => !sides[name]);
        }, shot.toString('base64'));
        if (missing.length)
          problems.push(`${deck} slide ${where.slide}: the still ${where.src} has no border on its ${missing.join(', ')} side(s) in print`);
      }
    }
    const small = new Map(); // slide => its smallest label
    const note = (slide, size, what) => {
      if (size < minimumLabel - 0.05 && (!small.has(slide) || size < small.get(slide).size)) small.set(slide, { size, what });
    };
    for (const label of found.inline) note(label.slide, label.size, `"${label.text}"`);
    for (const image of found.images) {
      const labels = await labelsOf(page, path.resolve(options.dist, decodeURI(image.src)));
      if (!labels.width || !labels.height) continue;
      const drawn = Math.min(image.width / labels.width, image.height / labels.height);
      for (const text of labels.texts) note(image.slide, text.size * drawn, `"${text.text}" in ${image.src}`);
    }
    for (const picture of found.rasters) {
      const name = picture.src.replace(/^figures\/generated\//, '');
      const known = textSizes[name];
      if (!known) {
        const problem = `${deck} slide ${picture.slide}: ${picture.src} has no known text size (draw it with figures.txt, text=PX)`;
        if (!problems.includes(problem)) problems.push(problem);
        continue;
      }
      // Where the picture is drawn: an <img> fills its box; a background is fitted into it.
      const drawn = Math.min(picture.width / known.width, picture.height / known.height);
      const [w, h] = picture.fit ? [known.width * drawn, known.height * drawn] : [picture.width, picture.height];
      const left = picture.fit ? picture.left + (picture.width - w) / 2 : picture.left;
      const top = picture.fit ? picture.top + (picture.height - h) / 2 : picture.top;
      if (known.text > 0) note(picture.slide, known.text * drawn, `text in ${picture.src} (${known.text} px in the picture, drawn at ${drawn.toFixed(2)}x)`);
      const gap = Math.min(left, top, 1280 - left - w, 720 - top - h);
      if (gap < margin - 0.5) {
        const problem = `${deck} slide ${picture.slide}: ${picture.src} is ${Math.max(0, gap).toFixed(0)} px from the slide's edge (at least ${margin})`;
        if (!problems.includes(problem)) problems.push(problem);
      }
    }
    for (const [slide, { size, what }] of [...small].sort((a, b) => a[0] - b[0])) {
      const problem = `${deck} slide ${slide}: label ${what} is ${size.toFixed(1)} px on the slide (at least ${minimumLabel})`;
      if (!problems.includes(problem)) problems.push(problem);
    }
  }
} finally {
  await browser.close();
}
for (const problem of problems) console.error(problem);
if (problems.length) {
  console.error(`check-layout: ${problems.length} slide(s) with content cut off, labels under ${minimumLabel} px or a screenshot at the slide's edge`);
  process.exit(1);
}
console.log(`check-layout: ${slides} slides, all content inside the slide, every diagram label at least ${minimumLabel} px`);
