#!/usr/bin/env node
// inline-images.mjs - the decks as the PDF converter gets them: every image inside the deck.
//
//     node inline-images.mjs --in build/decks --out build/pdf
//
// Why: Marp prints a PDF in Chromium, which may only read the deck's local images with
// --allow-local-files, and then warns "Insecure local file accessing" for every deck. With
// each image written into the deck as a data: URL there is nothing local to read, no flag
// and no warning; a missing image fails here, naming it. <script src> lines (the
// interactive figures) and the animations (<img class="anim">) are left out: the PDF shows
// each one's still. A link to another lecture's page (`[Title](02-name.html)`) becomes its
// title and PDF file name as plain text: Chromium would print it as a file:// link to the build
// machine's disk, dead in a student's handout.
import fs from 'node:fs';
import path from 'node:path';

const types = { '.svg': 'image/svg+xml', '.png': 'image/png', '.apng': 'image/apng' };

function parseArguments(argv) {
  const options = {};
  for (let i = 0; i < argv.length; i += 2) options[argv[i].replace(/^--/, '')] = argv[i + 1];
  if (!options.in || !options.out) throw new Error('usage: inline-images.mjs --in DIR --out DIR');
  return options;
}

// A data: URL of an image file; throws naming the file when it does not exist.
export function dataUrl(file) {
  const type = types[path.extname(file)];
  if (!type) throw new Error(`${file}: not an image this tool knows (${Object.keys(types).join(' ')})`);
  if (!fs.existsSync(file)) throw new Error(`${file}: no such image`);
  return `data:${type};base64,${fs.readFileSync(file).toString('base64')}`;
}

function inline(markdown, folder) {
  return markdown
    .split('\n')
    .filter((line) => !/^\s*<script\b[^>]*\bsrc=/.test(line))
    .join('\n')
    .replace(/(!\[[^\]]*\]\()(figures\/[^)\s]+)/g, (_, head, file) => head + dataUrl(path.join(folder, file)))
    .replace(/<img\b[^>]*\bclass="anim"[^>]*>/g, '') // the PDF shows the still
    .replace(/(?<!!)\[([^\]]+)\]\(([\w-]+)\.html(#[^)]*)?\)/g, (_, text, name) =>
      name === 'index' ? `${text} (index.html, beside the PDFs)` : `${text} (${name}.pdf)`)
    .replace(/(<img\b[^>]*\bsrc=")(figures\/[^"]+)/g, (_, head, file) => head + dataUrl(path.join(folder, file)))
    .replace(/(<image\b[^>]*\bhref=")(figures\/[^"]+)/g, (_, head, file) => head + dataUrl(path.join(folder, file)));
}

function main() {
  const options = parseArguments(process.argv.slice(2));
  fs.mkdirSync(options.out, { recursive: true });
  const decks = fs.readdirSync(options.in).filter((f) => f.endsWith('.md')).sort();
  for (const deck of decks)
    fs.writeFileSync(path.join(options.out, deck), inline(fs.readFileSync(path.join(options.in, deck), 'utf8'), options.in));
  console.error(`inline-images: ${decks.length} deck(s) with their images inside, in ${options.out}`);
}

if (import.meta.url === `file://${process.argv[1]}`) {
  try {
    main();
  } catch (error) {
    console.error(`inline-images: ${error.message}`);
    process.exit(1);
  }
}
