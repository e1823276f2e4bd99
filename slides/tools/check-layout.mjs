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
      sections.forEach((section, index) => {
        const box = section.getBoundingClientRect();
        if (box.height === 0) return;
        const scale = box.height / section.offsetHeight;
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
      return { result, count: sections.length, images, inline };
    });
    if (media === 'screen') {
      slides += found.count;
      for (const problem of found.result) problems.push(`${deck} ${problem}`);
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
  console.error(`check-layout: ${problems.length} slide(s) with content cut off or diagram labels under ${minimumLabel} px`);
  process.exit(1);
}
console.log(`check-layout: ${slides} slides, all content inside the slide, every diagram label at least ${minimumLabel} px`);
