#!/usr/bin/env node
// deck-extras.mjs - the navigation around the decks, made from the decks themselves.
//
//     node deck-extras.mjs --decks build/decks --notes build/notes --dist dist
//
// 1. Each deck gets a last slide linking the previous and the next lecture and the index.
// 2. Each deck gets a notes deck for the lecturer (build/notes/NN-...-notes.md): one page a
//    slide, its heading and its speaker notes as text, converted to PDF beside the slides.
//    With --pictures DIR (the slides as PNG, NAME.001.png..., made by Marp --images) only
//    the notes decks are written, each page with its slide's picture above the notes.
// 3. dist/index.html lists every lecture with its outline: each heading links to its slide
//    (deck.html#N), with the PDF and the notes PDF when they were made (build.sh writes the
//    index once more after the PDFs, with --index-only 1).
import fs from 'node:fs';
import path from 'node:path';
import { dataUrl } from './inline-images.mjs';
import { isDirective } from './marp-directives.mjs';

function parseArguments(argv) {
  const options = {};
  for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
  for (const needed of ['decks', 'notes', 'dist']) if (!options[needed]) throw new Error(`missing --${needed}`);
  return options;
}

// Front matter and slides of one deck (split on --- outside code fences).
function split(markdown) {
  const lines = markdown.split('\n');
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
    } else current.push(line);
  }
  slides.push(current.join('\n'));
  return { frontMatter: lines.slice(0, start).join('\n'), slides };
}

const titleOf = (markdown, fallback) => (markdown.match(/^title:\s*"?([^"\n]*)"?\s*$/m) || [])[1] || fallback;
const headingOf = (slide) => ((slide.match(/^#{1,2} +(.*)$/m) || [])[1] || '').trim();
const notesOf = (slide) =>
  [...slide.matchAll(/<!--([\s\S]*?)-->/g)]
    .map((m) => m[1].trim())
    .filter((text) => text && !isDirective(text) && !/^include:/.test(text));
const escapeHtml = (text) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
const plain = (text) => text.replace(/\$+([^$]*)\$+/g, '$1').replace(/[*`]/g, '');

// The lecturer's notes: one page a slide (a portrait page: the slide's picture when there is
// one, then its notes).
function writeNotes(deck, options) {
  const pictureOf = (number) => {
    if (!options.pictures) return [];
    const file = path.join(options.pictures, `${deck.name}.${String(number).padStart(3, '0')}.png`);
    return fs.existsSync(file) ? [`<img class="slide-picture" src="${dataUrl(file)}" alt="slide ${number}">`, ''] : [];
  };
  const pages = deck.slides
    .map((slide, i) => ({ number: i + 1, heading: headingOf(slide), notes: notesOf(slide) }))
    .filter((page) => page.heading || page.notes.length);
  const notes = [
    '---', 'marp: true', 'theme: hitbox', 'size: notes', 'paginate: false', `title: "${deck.title} · speaker notes"`, '---', '',
    // The title goes on the first slide's page, not on a page of its own.
    `<!-- _class: notes -->`, '', `# ${deck.title}: speaker notes`, '',
    ...pages.flatMap((page, index) => [...(index ? ['---', '', '<!-- _class: notes -->', ''] : []),
      `## ${page.number}. ${plain(page.heading) || '(no heading)'}`, '', ...pictureOf(page.number),
      ...page.notes.map((n) => escapeHtml(n).replace(/\n(?!\n)/g, ' ') + '\n')]),
  ];
  fs.writeFileSync(path.join(options.notes, `${deck.name}-notes.md`), notes.join('\n'));
}

function main() {
  const options = parseArguments(process.argv.slice(2));
  fs.mkdirSync(options.notes, { recursive: true });
  const names = fs.readdirSync(options.decks).filter((f) => f.endsWith('.md')).sort();
  const decks = names.map((file) => {
    const markdown = fs.readFileSync(path.join(options.decks, file), 'utf8');
    return { file, name: file.replace(/\.md$/, ''), markdown, title: titleOf(markdown, file), ...split(markdown) };
  });

  if (options.pictures) {
    for (const deck of decks) writeNotes(deck, options);
  } else if (!options['index-only']) decks.forEach((deck, index) => {
    const previous = decks[index - 1];
    const next = decks[index + 1];
    const links = [];
    if (next) links.push(`**Next:** [${next.title}](${next.name}.html)`);
    if (previous) links.push(`Previous: [${previous.title}](${previous.name}.html)`);
    links.push('[All lectures](index.html)');
    const navigation = ['', '<!-- _class: lead -->', '<!-- _paginate: false -->', '',
      `# ${next ? 'Next lecture' : 'End of the unit'}`, '', ...links.map((l) => `${l}\n`),
      '<!--', next
        ? 'Before the class leaves, say in one sentence what the next lecture adds to this one, and show where the decks are: the list of all lectures, each with its outline.'
        : 'The end of the unit: point the class to the list of all lectures, each with its outline, for revision, and to the previous lecture.', '-->', ''];
    fs.writeFileSync(path.join(options.decks, deck.file), `${deck.markdown.replace(/\s*$/, '\n')}\n---\n${navigation.join('\n')}`);

    writeNotes(deck, options);
  });

  // The index: every lecture, its outline linking to the slides.
  const items = decks.map((deck) => {
    const files = [];
    if (fs.existsSync(path.join(options.dist, `${deck.name}.pdf`))) files.push(`<a href="${deck.name}.pdf">PDF</a>`);
    if (fs.existsSync(path.join(options.dist, `${deck.name}-notes.pdf`)))
      files.push(`<a href="${deck.name}-notes.pdf">speaker notes (PDF)</a>`);
    const outline = split(deck.markdown).slides
      .map((slide, i) => ({ number: i + 1, heading: headingOf(slide) }))
      .filter((s) => s.heading && s.number > 1)
      .map((s) => `<li><a href="${deck.name}.html#${s.number}">${escapeHtml(plain(s.heading))}</a></li>`);
    return `<li><details><summary><a href="${deck.name}.html">${escapeHtml(deck.title)}</a>` +
      `${files.length ? ` (${files.join(', ')})` : ''}</summary><ol class="outline">${outline.join('')}</ol></details></li>`;
  });
  const page = `<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>Hitbox lectures</title>
<style>body{font-family:sans-serif;font-size:22px;margin:40px;max-width:60em}li{margin:8px 0}
.outline{font-size:18px;columns:2}summary{cursor:pointer}</style></head>
<body><h1>Hitbox: collision detection lectures</h1>
<p>Click a lecture's arrow for its outline; each line opens that slide.</p><ol>
${items.join('\n')}
</ol><p>In a deck: P for the presenter view with the speaker notes, F for full screen.</p></body></html>
`;
  fs.writeFileSync(path.join(options.dist, 'index.html'), page);
  console.error(`deck-extras: ${decks.length} deck(s): navigation slides, notes decks, index`);
}

try {
  main();
} catch (error) {
  console.error(`deck-extras: ${error.message}`);
  process.exit(1);
}
