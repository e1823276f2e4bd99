#!/usr/bin/env node
// check-decks.mjs - the lecture-quality checks that a build alone does not make.
//
//     node check-decks.mjs --decks build/decks --dist dist --concepts concepts.txt --src src
//
// - a slide's caption and speaker notes name only code its excerpt contains: every code-like
//   name in them (`inline code`, a camelCase name, a member like hit.time) is in the slide's
//   code, so a caption cannot promise what the excerpt was cut before;
// - every figure (figures/*.svg, every output of figures.txt and, with --labs DIR, every
//   lab's screenshot.png unless a figure its program draws is on a slide) is used by a deck;
// - every slide has speaker notes (an HTML comment that is not a Marp directive) that say
//   something to the instructor: at least `notesWords` words besides a "Next: ..." pointer,
//   and no authoring leftovers (the names of the sources the decks were written from, such
//   as "the course lecture" or "the top-down report", mean nothing to the one presenting);
// - no slide shows more code than fits at lecture-hall size: 16 lines, and no line longer
//   than the 78 characters that fit at the theme's 24px (code never shrinks or wraps);
// - every code excerpt has balanced brackets ( ) [ ] { } outside strings and comments, so
//   an excerpt cut in the middle of a statement fails;
// - no words for insiders on what the students see (slides and code, not the notes):
//   the course's internal reference documents ("seed 002"), "old course code", "last year";
// - every image a deck links to exists beside it;
// - every deck in src/ became an HTML file, and no HTML file loads anything from the
//   network (the decks must work offline in a lecture hall);
// - every concept in concepts.txt ("name => regular expression") is on at least one slide
//   (speaker notes do not count: the students must see it).
import fs from 'node:fs';
import path from 'node:path';
import { isDirective } from './marp-directives.mjs';

// How much code fits under a heading at the theme's 24px: 16 lines of 78 characters.
// include-regions.mjs formats every excerpt to this width with the project's clang-format.
const codeFit = { lines: 16, columns: 78 };
// Words for the course team, never for students: the internal reference documents are
// called seeds, and "old"/"last year's" material is not the students' business. Checked on
// everything a student sees (headings, bullets, code), not on the speaker notes.
const insiderWords = [
  /\bseeds?\s*(?:documents?\s*)?0\d\d\b/i,
  /\bseed\s+(?:documents?|files?|ideas?)\b/i,
  /\b(?:the|our|course's|course)\s+seeds?\b/i,
  /\bold course(?:'s)?\s+(?:code|lecture|framework|slides)\b/i,
  /\bthe old framework\b/i,
  /\blast year'?s?\b/i,
];
// Speaker notes that help the one presenting: what to say, what to ask, what is left out.
// A summary slide whose notes only say "Next: ..." gives them nothing.
const notesWords = 12;
const nextPointer = /^\s*(?:Next|Last deck)\s*:.*$/gim;
// The sources the decks were written from, by the names their authors used for them.
const authoringLeftovers = [
  /\bthe course(?:'s)? (?:old )?(?:collision )?(?:lecture|code)\b/i,
  /\bcourse lecture(?:'s)?\b/i,
  /\b(?:the )?top-down (?:game )?report\b/i,
  /\bthe report(?:'s)?\b/i,
  /\bseeds?\s*(?:documents?\s*)?0\d\d\b/i,
  /\bseed\s+(?:documents?|files?|ideas?)\b/i,
];


function parseArguments(argv) {
  const options = {};
  for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
  for (const needed of ['decks', 'dist', 'concepts', 'src', 'figures'])
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

// The code blocks of a slide: [{language, lines}].
function codeBlocks(text) {
  const blocks = [];
  let current = null;
  for (const line of text.split('\n')) {
    const fence = line.match(/^\s*```\s*(\S*)/);
    if (fence && !current) current = { language: fence[1], lines: [] };
    else if (fence) {
      blocks.push(current);
      current = null;
    } else if (current) current.lines.push(line);
  }
  return blocks;
}

// The first bracket problem of a C-like excerpt, or null: strings, character literals and
// comments are skipped, every ( [ { must close in order.
function bracketProblem(lines) {
  const source = lines.join('\n');
  const closing = { ')': '(', ']': '[', '}': '{' };
  const stack = [];
  let line = 1;
  for (let i = 0; i < source.length; i++) {
    const c = source[i];
    if (c === '\n') line++;
    else if (c === '/' && source[i + 1] === '/') {
      while (i < source.length && source[i] !== '\n') i++;
      i--;
    } else if (c === '/' && source[i + 1] === '*') {
      const end = source.indexOf('*/', i + 2);
      line += (source.slice(i, end < 0 ? source.length : end).match(/\n/g) || []).length;
      i = end < 0 ? source.length : end + 1;
    } else if (c === '"' || c === "'") {
      let j = i + 1;
      while (j < source.length && source[j] !== c && source[j] !== '\n') j += source[j] === '\\' ? 2 : 1;
      i = j;
    } else if ('([{'.includes(c)) stack.push({ c, line });
    else if (c in closing) {
      const open = stack.pop();
      if (!open) return `'${c}' on code line ${line} closes nothing`;
      if (open.c !== closing[c]) return `'${c}' on code line ${line} closes '${open.c}' of line ${open.line}`;
    }
  }
  if (stack.length) return `'${stack[stack.length - 1].c}' on code line ${stack[stack.length - 1].line} is never closed (an excerpt cut short?)`;
  return null;
}

// Problems with the code of one slide.
function codeProblems(text) {
  const problems = [];
  let count = 0;
  for (const block of codeBlocks(text)) {
    count += block.lines.length;
    block.lines.forEach((line, index) => {
      if (line.length > codeFit.columns)
        problems.push(`code line ${index + 1} has ${line.length} characters (at most ${codeFit.columns} fit at 24px): ${line.trim()}`);
    });
    if (/^(cpp|c\+\+|c|js|javascript|cmake)?$/i.test(block.language)) {
      const problem = bracketProblem(block.lines);
      if (problem) problems.push(`unbalanced brackets: ${problem}`);
    }
  }
  if (count > codeFit.lines) problems.push(`${count} lines of code (at most ${codeFit.lines} fit)`);
  return problems;
}

// Code-like names: `inline code`, camelCase names, members (hit.time). Formulas ($...$)
// and file names are not code. In the notes (membersOnly) only `inline code` and members
// count: a note may name a function the class met elsewhere, not a variable this excerpt lacks.
function codeNames(prose, membersOnly) {
  const text = prose.replace(/\$\$[\s\S]*?\$\$|\$[^$\n]*\$/g, ' ');
  const names = new Set();
  for (const m of text.matchAll(/`([^`\n]+)`/g)) names.add(m[1]);
  const bare = text.replace(/`[^`\n]*`/g, ' ').replace(/\b[\w./-]+\.(?:md|svg|png|apng|cpp|h|html|pdf|txt|sh)\b/g, ' ');
  if (!membersOnly) for (const m of bare.matchAll(/\b[a-z]+[A-Z]\w*\b/g)) names.add(m[0]);
  for (const m of bare.matchAll(/\b[a-z]\w*\.[a-z]\w+\b/g)) names.add(m[0]);
  return [...names];
}

// Names a code slide's caption or notes use that its code does not contain.
function namesNotShown(text) {
  const code = codeBlocks(text).map((b) => b.lines.join('\n')).join('\n');
  if (!code) return [];
  const withoutCode = text.replace(/```[\s\S]*?```/g, ' ');
  const notes = [...withoutCode.matchAll(/<!--([\s\S]*?)-->/g)].map((m) => m[1]).join('\n');
  const names = [...codeNames(visibleText(withoutCode), false), ...codeNames(notes, true)];
  return [...new Set(names)].filter((name) => !code.includes(name));
}

function notesOf(text) {
  return [...text.matchAll(/<!--([\s\S]*?)-->/g)].map((m) => m[1]).filter((c) => !isDirective(c) && c.trim() !== '');
}

function hasNotes(text) {
  return notesOf(text).length > 0;
}

// What is wrong with a slide's notes: too thin to help, or an authoring leftover.
function notesProblems(text) {
  const notes = notesOf(text).join('\n');
  if (!notes) return [];
  const problems = [];
  const words = notes.replace(nextPointer, ' ').split(/\s+/).filter((w) => /\w/.test(w)).length;
  if (words < notesWords)
    problems.push(`speaker notes say too little (${words} words besides a "Next:" line; at least ${notesWords}): ` +
      'what should the instructor say, ask or point at here?');
  for (const leftover of authoringLeftovers) {
    const found = notes.match(leftover);
    if (found) problems.push(`speaker notes name a source by its authoring name: "${found[0]}" (say what it is, or what it says)`);
  }
  return problems;
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
      for (const problem of notesProblems(slide.text)) problems.push(`${where}: ${problem}`);
      for (const problem of codeProblems(slide.text)) problems.push(`${where}: ${problem}`);
      for (const name of namesNotShown(slide.text))
        problems.push(`${where}: the caption or notes name "${name}", which the slide's code does not contain`);
      const visible = visibleText(slide.text);
      for (const word of insiderWords) {
        const found = visible.match(word);
        if (found) problems.push(`${where}: words for insiders on the slide: "${found[0]}"`);
      }
      const images = [...slide.text.matchAll(/!\[[^\]]*\]\(([^)\s]+)\)/g), ...slide.text.matchAll(/<img\b[^>]*\bsrc="([^"]+)"/g)];
      for (const image of images) {
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

  // Every figure is shown by some deck (the sources, before the build adds navigation).
  const linked = fs.readdirSync(options.src).filter((f) => f.endsWith('.md'))
    .map((f) => fs.readFileSync(path.join(options.src, f), 'utf8')).join('\n');
  const figures = fs.readdirSync(options.figures).filter((f) => f.endsWith('.svg')).map((f) => `figures/${f}`);
  const list = path.join(options.figures, '..', 'figures.txt');
  const drawnBy = new Map(); // lab folder => the figures its program draws
  if (fs.existsSync(list))
    for (const line of fs.readFileSync(list, 'utf8').split(/\r?\n/))
      if (line.trim() && !line.startsWith('#')) {
        const [name, program = ''] = line.trim().split(/\s+/);
        figures.push(`figures/generated/${name}`);
        const lab = /^labs\/([^/]+)\//.exec(program);
        if (lab) drawnBy.set(lab[1], [...(drawnBy.get(lab[1]) || []), `figures/generated/${name}`]);
      }
  // Every lab is on a slide: its screenshot.png, or a figure its program draws (a crop of it
  // that a lecture hall can read).
  if (options.labs)
    for (const lab of fs.readdirSync(options.labs))
      if (fs.existsSync(path.join(options.labs, lab, 'screenshot.png')) &&
          !(drawnBy.get(lab) || []).some((figure) => linked.includes(figure)))
        figures.push(`figures/labs/${lab.slice(0, 2)}.png`);
  for (const figure of figures)
    if (!linked.includes(figure)) problems.push(`${figure}: used by no deck (use it on a slide, or remove it)`);

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
