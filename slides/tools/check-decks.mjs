#!/usr/bin/env node
// check-decks.mjs - the lecture-quality checks that a build alone does not make.
//
//     node check-decks.mjs --decks build/decks --dist dist --concepts concepts.txt --src src
//
// - every slide has speaker notes (an HTML comment that is not a Marp directive);
// - no slide shows more code than fits at lecture-hall size (16 lines, long lines counted
//   as the screen lines they wrap to);
// - every image a deck links to exists beside it;
// - every deck in src/ became an HTML file, and no HTML file loads anything from the
//   network (the decks must work offline in a lecture hall);
// - every concept in concepts.txt ("name => regular expression") is on at least one slide
//   (speaker notes do not count: the students must see it).
import fs from 'node:fs';
import path from 'node:path';

// How much code fits under a heading, in screen lines: 16 lines of 78 characters at the
// theme's 24px, or 19 lines of 98 characters on a `wide-code` slide (20px). A longer source
// line wraps and takes more than one screen line.
const codeFit = { normal: { lines: 16, columns: 78 }, wide: { lines: 19, columns: 98 } };
// Marp's directives (<!-- _class: lead -->, <!-- paginate: false -->); any other comment is
// a speaker note, even one that starts with "Next:".
const directive = /^\s*_?(class|paginate|header|footer|theme|style|size|math|headingDivider|backgroundColor|backgroundImage|backgroundPosition|backgroundRepeat|backgroundSize|color|marp|title|description|author|image|keywords|url|transition|lang)\s*:/;

function parseArguments(argv) {
  const options = {};
  for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
  for (const needed of ['decks', 'dist', 'concepts', 'src'])
    if (!options[needed]) throw new Error(`missing --${needed}`);
  return options;
}

// Slides of one deck: [{number, text}] without the front matter.
function slidesOf(markdown) {
  const lines = markdown.split(/\r?\n/);
  let start = 0;
  if (lines[0] === '---') start = lines.indexOf('---', 1) + 1;
  const slides = [];
  let current = [];
  let inFence = false;
  for (const line of lines.slice(start)) {
    if (/^\s*```/.test(line)) inFence = !inFence;
    if (!inFence && line === '---') {
      slides.push(current.join('\n'));
      current = [];
    } else {
      current.push(line);
    }
  }
  slides.push(current.join('\n'));
  return slides.map((text, index) => ({ number: index + 1, text })).filter((s) => s.text.trim() !== '');
}

// Screen lines of code on a slide, and how many fit.
function codeLines(text) {
  const fit = /<!--\s*_class:\s*wide-code\s*-->/.test(text) ? codeFit.wide : codeFit.normal;
  let count = 0;
  let inFence = false;
  for (const line of text.split('\n')) {
    if (/^\s*```/.test(line)) inFence = !inFence;
    else if (inFence) count += Math.max(1, Math.ceil(line.length / fit.columns));
  }
  return { count, fit: fit.lines };
}

function hasNotes(text) {
  const comments = [...text.matchAll(/<!--([\s\S]*?)-->/g)].map((m) => m[1]);
  return comments.some((c) => !directive.test(c) && c.trim() !== '');
}

function visibleText(text) {
  return text.replace(/<!--[\s\S]*?-->/g, ' ');
}

function main() {
  const options = parseArguments(process.argv.slice(2));
  const problems = [];
  const decks = fs.readdirSync(options.decks).filter((f) => f.endsWith('.md')).sort();
  const everything = [];

  for (const deck of decks) {
    const markdown = fs.readFileSync(path.join(options.decks, deck), 'utf8');
    for (const slide of slidesOf(markdown)) {
      const where = `${deck} slide ${slide.number}`;
      if (!hasNotes(slide.text)) problems.push(`${where}: no speaker notes (an HTML comment)`);
      const code = codeLines(slide.text);
      if (code.count > code.fit) problems.push(`${where}: ${code.count} screen lines of code (at most ${code.fit} fit)`);
      for (const image of slide.text.matchAll(/!\[[^\]]*\]\(([^)\s]+)\)/g)) {
        if (/^https?:/.test(image[1])) problems.push(`${where}: image ${image[1]} is on the network`);
        else if (!fs.existsSync(path.join(options.decks, image[1])))
          problems.push(`${where}: image ${image[1]} does not exist`);
      }
      everything.push(visibleText(slide.text));
    }
  }

  for (const source of fs.readdirSync(options.src).filter((f) => f.endsWith('.md'))) {
    const html = path.join(options.dist, source.replace(/\.md$/, '.html'));
    if (!fs.existsSync(html)) {
      problems.push(`${source}: no ${html}`);
      continue;
    }
    const page = fs.readFileSync(html, 'utf8');
    const remote = page.match(/(?:src|href)\s*=\s*["']https?:[^"']*|url\(\s*["']?https?:[^)]*|@import\s+["']https?:[^"']*/);
    if (remote) problems.push(`${html}: loads from the network: ${remote[0]}`);
  }

  const allText = everything.join('\n');
  let conceptCount = 0;
  for (const line of fs.readFileSync(options.concepts, 'utf8').split(/\r?\n/)) {
    if (line.trim() === '' || line.startsWith('#')) continue;
    const separator = line.indexOf('=>');
    if (separator < 0) throw new Error(`concepts.txt: no "=>" in: ${line}`);
    const name = line.slice(0, separator).trim();
    const pattern = line.slice(separator + 2).trim();
    conceptCount++;
    if (!new RegExp(pattern, 'i').test(allText)) problems.push(`concept not on any slide: ${name} (/${pattern}/i)`);
  }

  for (const problem of problems) console.error(problem);
  if (problems.length) {
    console.error(`check-decks: ${problems.length} problem(s)`);
    process.exit(1);
  }
  console.log(`check-decks: ${decks.length} deck(s), ${everything.length} slides with notes, ` +
    `${conceptCount} concepts found, offline HTML`);
}

try {
  main();
} catch (error) {
  console.error(`check-decks: ${error.message}`);
  process.exit(1);
}
