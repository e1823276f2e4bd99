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
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  const decks = fs.readdirSync(options.dist).filter((f) => /^\d\d-.*\.html$/.test(f)).sort();
  for (const deck of decks) {
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
      return { result, count: sections.length };
    });
    slides += found.count;
    for (const problem of found.result) problems.push(`${deck} ${problem}`);
  }
} finally {
  await browser.close();
}
for (const problem of problems) console.error(problem);
if (problems.length) {
  console.error(`check-layout: ${problems.length} slide(s) with content cut off`);
  process.exit(1);
}
console.log(`check-layout: ${slides} slides, all content inside the slide`);
