#!/usr/bin/env node
// include-regions.mjs - turns the deck sources into the decks Marp converts.
//
// Why: code on a slide must be exactly what the framework and the labs contain, so a deck
// never quotes code by hand. It names a region instead, and this script copies it in:
//
//     <!-- include: framework/hitbox/geometry/Overlap.cpp#aabb-overlap -->
//     <!-- include: #pong-serve -->            (path left out: any source file may hold it)
//     <!-- include: #aabb-contact lines 1-16 key "return" -->  (part of a long region)
//     <!-- include: #sat-axis-test lines 11-17,24-25 key "push <= 0.f" -->  (parts, "// ...")
//
// Part of a region must name its key line: the excerpt has to contain that text, so an
// excerpt cut before the line the slide is about fails the build (lines count in the region
// as written, marker lines and lab starter code left out). Parts with code between them
// are joined by a `// ...` line.
// A region is marked in a source file by a line `// [slide:NAME]` and a line `// [/slide]`.
// The include line becomes a fenced code block of the region: marker lines left out, the
// common indentation removed. In lab sources, the task markers and the starter code
// (`// BEGIN TASK n`, `// STARTER TASK n` ... `// END TASK n`) are left out too, and a slide
// may show the code around a task, never the task's answer ("graded answer" below). A missing file or region is an error naming the deck and line:
//     src/01-bounding-volumes.md:42: region aabb-overlap not found in framework/x.cpp
//
// Usage:
//     node include-regions.mjs --root REPO --src DIR --out DIR [--allow-missing] [--list]
// --allow-missing  drafts only: a missing region becomes a visible placeholder (exit 0)
// --list           print every region the decks use ("deck:line NAME FILE") and check them
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const includeLine = /^\s*<!--\s*include:\s*([^#\s]*)#([A-Za-z0-9_.-]+)(?:\s+lines\s+([\d,\s-]+?))?(?:\s+key\s+"([^"]+)")?\s*-->\s*$/;
const regionStart = /^\s*\/\/\s*\[slide:([A-Za-z0-9_.-]+)\]\s*$/;
const regionEnd = /^\s*\/\/\s*\[\/slide\]\s*$/;
const taskBegin = /^\s*\/\/\s*BEGIN TASK\b/;
const taskStarter = /^\s*\/\/\s*STARTER TASK\b/;
const taskEnd = /^\s*\/\/\s*END TASK\b/;
// Where regions may live: the project's sources, never generated or installed files.
const skippedFolders = new Set(['.git', 'node_modules', 'slides', 'out', 'dist']);
const sourceExtensions = new Set(['.cpp', '.h', '.hpp', '.cc', '.inl', '.cmake']);
// Code that does not fit a slide at lecture-hall size (see README "Writing a deck").
const maxLinesPerSlide = 16;
// The theme's 24px code fits 78 characters a line (see theme/hitbox.css). The sources are
// formatted for 100 columns, so a C++ excerpt is formatted again by the project's own
// .clang-format with this column limit: the same tokens, comments re-wrapped, lines broken
// where clang-format would break them. check-decks.mjs fails on any line still too long.
const slideColumns = 78;

function parseArguments(argv) {
  const options = { allowMissing: false, list: false };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (arg === '--root') options.root = argv[++i];
    else if (arg === '--src') options.src = argv[++i];
    else if (arg === '--out') options.out = argv[++i];
    else if (arg === '--allow-missing') options.allowMissing = true;
    else if (arg === '--list') options.list = true;
    else throw new Error(`unknown argument ${arg}`);
  }
  if (!options.root || !options.src || (!options.out && !options.list))
    throw new Error('usage: include-regions.mjs --root REPO --src DIR --out DIR [--allow-missing] [--list]');
  return options;
}

function sourceFiles(root, folder = '') {
  const found = [];
  for (const entry of fs.readdirSync(path.join(root, folder), { withFileTypes: true })) {
    const relative = folder ? `${folder}/${entry.name}` : entry.name;
    if (entry.isDirectory()) {
      // build*, handout*: generated trees (see .gitignore).
      if (skippedFolders.has(entry.name) || /^(build|handout)/.test(entry.name)) continue;
      found.push(...sourceFiles(root, relative));
    } else if (sourceExtensions.has(path.extname(entry.name)) || entry.name === 'CMakeLists.txt') {
      found.push(relative);
    }
  }
  return found;
}

// Every region of one file: name -> {lines, startLine}. Errors for broken markers.
function regionsOf(root, file) {
  const regions = new Map();
  const lines = fs.readFileSync(path.join(root, file), 'utf8').split(/\r?\n/);
  let open = null;
  lines.forEach((line, index) => {
    const start = line.match(regionStart);
    if (start) {
      if (open) throw new Error(`${file}:${index + 1}: region ${start[1]} starts inside region ${open.name}`);
      if (regions.has(start[1])) throw new Error(`${file}:${index + 1}: region ${start[1]} defined twice`);
      const before = lines.slice(0, index).reverse().find((l) => l.trim() !== '' && !regionEnd.test(l));
      open = { name: start[1], startLine: index + 1, lines: [], before: before ?? '' };
    } else if (regionEnd.test(line)) {
      if (!open) throw new Error(`${file}:${index + 1}: [/slide] without a [slide:NAME] before it`);
      open.after = lines.slice(index + 1).find((l) => l.trim() !== '' && !regionStart.test(l)) ?? '';
      regions.set(open.name, open);
      open = null;
    } else if (open) {
      open.lines.push(line);
    }
  });
  if (open) throw new Error(`${file}:${open.startLine}: region ${open.name} has no [/slide]`);
  return regions;
}

// The solution's lines of a lab region: task markers and starter code dropped.
function withoutTaskMarkers(lines) {
  return taggedSolution(lines).map((l) => l.text);
}
// The same lines, each with the task it answers ("TASK 3") or null outside a task block.
function taggedSolution(lines) {
  const kept = [];
  let inStarter = false;
  let task = null;
  for (const line of lines) {
    if (taskStarter.test(line)) inStarter = true;
    else if (taskEnd.test(line)) {
      inStarter = false;
      task = null;
    } else if (taskBegin.test(line)) task = line.match(/TASK\s*\d*/)[0];
    else if (!inStarter) kept.push({ text: line, task });
  }
  return kept;
}

function dedent(lines) {
  const indents = lines.filter((l) => l.trim() !== '').map((l) => l.match(/^[ \t]*/)[0].length);
  const common = indents.length ? Math.min(...indents) : 0;
  const result = lines.map((l) => l.slice(common).replace(/\s+$/, ''));
  while (result.length && result[0] === '') result.shift();
  while (result.length && result[result.length - 1] === '') result.pop();
  return result;
}

// An excerpt is formatted inside a function of its own (see fitToSlide), one indent deep.
const wrapperIndent = '    ';
// The repository's .clang-format with the slide's column limit, in a folder of its own; in
// its subfolder `body`, the limit plus the wrapper's indent.
function slideStyleFolder(root) {
  const style = fs.readFileSync(path.join(root, '.clang-format'), 'utf8');
  const folder = fs.mkdtempSync(path.join(os.tmpdir(), 'hitbox-slide-style-'));
  fs.mkdirSync(path.join(folder, 'body'));
  fs.writeFileSync(path.join(folder, '.clang-format'), style.replace(/^ColumnLimit:.*$/m, `ColumnLimit: ${slideColumns}`));
  fs.writeFileSync(path.join(folder, 'body', '.clang-format'),
    style.replace(/^ColumnLimit:.*$/m, `ColumnLimit: ${slideColumns + wrapperIndent.length}`));
  return folder;
}

// An excerpt formatted to fit the slide (C++ only; lines that already fit stay as they are).
// Statements from inside a function body (`inBody`) go inside a function of their own before
// clang-format reads them: alone at file scope they are parsed as declarations, and
// `box.height * scale.y` came out as `box.height* scale.y` (a pointer type). Declarations
// (a whole function, a class's members) are formatted as they are.
function fitToSlide(code, language, styleFolder, inBody) {
  if (language !== 'cpp' || code.every((line) => line.length <= slideColumns)) return code;
  // Only the lines that are too long are formatted (--lines): the others stay as written.
  const shift = inBody ? 3 : 1;
  const tooLong = code.flatMap((line, index) => (line.length > slideColumns ? [`--lines=${index + shift}:${index + shift}`] : []));
  const indent = inBody ? wrapperIndent : '';
  const wrapped = [...(inBody ? ['void slideExcerpt()', '{'] : []), ...code.map((line) => (line ? indent + line : line)), ...(inBody ? ['}'] : [])];
  const formatted = execFileSync('clang-format', [`--assume-filename=${path.join(styleFolder, inBody ? 'body' : '', 'excerpt.cpp')}`, ...tooLong],
    { input: wrapped.join('\n') + '\n', encoding: 'utf8' }).replace(/\n+$/, '').split('\n');
  if (!inBody) return dedent(formatted);
  if (formatted[0] !== wrapped[0] || formatted[1] !== '{' || formatted[formatted.length - 1] !== '}')
    throw new Error(`clang-format changed the wrapper around an excerpt:\n${formatted.join('\n')}`);
  return dedent(formatted.slice(2, -1));
}

// Are the shown lines statements inside a function body? In a .cpp file, lines that are all
// indented (the project does not indent namespaces) are.
function shownInBody(file, lines, partList) {
  if (!file.endsWith('.cpp')) return false;
  const shown = partList.flatMap(([first, last]) => lines.slice(first - 1, last)).filter((l) => l.trim() !== '');
  return shown.length > 0 && shown.every((l) => /^[ \t]/.test(l));
}

function languageOf(file) {
  if (file.endsWith('.cmake') || file.endsWith('CMakeLists.txt')) return 'cmake';
  return 'cpp';
}

// --- An excerpt is a whole thing -------------------------------------------------------------
// A slide's excerpt (a whole region, or each part of one) must start and end on a statement
// boundary: what comes before its first line and what its last line ends with are read as
// C++ statement boundaries. Caught: a first line that continues the line before it (which
// ends in `=`, `,`, `(`, `&&`, `)` of an `if`...), a first comment line that continues a
// comment, a first line that is itself a continuation (`.x`, `&& b`, `else`); a last line
// that ends mid-statement (`if (best.hit)`, `a +`), a last line that is a comment about code
// the slide does not show, and a last line followed by its `else`. (Bracket balance is
// check-decks.mjs's.) Allman braces are the project's style, so `)` before a `{` line is a
// function or statement header: an excerpt may not start at its `{`.
const commentLine = (l) => /^\s*(\/\/|\/\*|\*)/.test(l);
// The code of a line without its trailing // comment (strings kept whole).
function codeOfLine(line) {
  let inString = null;
  for (let i = 0; i < line.length; i++) {
    const c = line[i];
    if (inString) {
      if (c === '\\') i++;
      else if (c === inString) inString = null;
    } else if (c === '"' || c === "'") inString = c;
    else if (c === '/' && line[i + 1] === '/') return line.slice(0, i).trim();
  }
  return line.trim();
}
// True when the line ends a statement (or opens/closes a block, or is a label/preprocessor).
function endsStatement(line) {
  const code = codeOfLine(line);
  if (code === '' || code.startsWith('#')) return true;
  return /[;{}]$/.test(code) || (/:$/.test(code) && !/::$/.test(code));
}
const continuationStart = /^\s*(\.|->|&&|\|\||\?|:(?!:)|\)|\]|[-+*\/%<>=!&|^,]\s|else\b|\{)/;
function wholeProblems(code, parts, region) {
  const problems = [];
  const lineAt = (n) => (n >= 1 && n <= code.length ? code[n - 1] : n < 1 ? region.before : region.after);
  // The line before line n (blank lines skipped; comment lines too when code is asked for).
  const previousLine = (n, codeOnly) => {
    for (let k = n - 1; k >= 1; k--)
      if (code[k - 1].trim() !== '' && !(codeOnly && commentLine(code[k - 1]))) return { line: code[k - 1], inside: true };
    return { line: region.before ?? '', inside: false };
  };
  const nextLine = (n) => {
    for (let k = n + 1; k <= code.length; k++) if (code[k - 1].trim() !== '') return code[k - 1];
    return region.after ?? '';
  };
  for (const [first, last] of parts) {
    const start = lineAt(first);
    const before = previousLine(first, false);
    const codeBefore = previousLine(first, true);
    if (continuationStart.test(start) && !commentLine(start))
      problems.push(`starts mid-statement at line ${first}: "${start.trim()}"`);
    else if (!commentLine(codeBefore.line) && !endsStatement(codeBefore.line))
      problems.push(`starts mid-statement at line ${first}: the line before it ("${codeBefore.line.trim()}") goes on`);
    else if (before.inside && commentLine(start) && commentLine(before.line))
      problems.push(`starts inside a comment at line ${first}: "${start.trim()}"`);
    const end = lineAt(last);
    if (commentLine(end))
      problems.push(`ends on a comment at line ${last} ("${end.trim()}"): about code the slide does not show`);
    else if (!endsStatement(end))
      problems.push(`ends mid-statement at line ${last}: "${end.trim()}"`);
    else if (/^\s*else\b/.test(nextLine(last)))
      problems.push(`ends at line ${last} before its "else"`);
  }
  return problems;
}

// --- A slide never hands students a graded answer -------------------------------------------
// A lab's task is graded: the code between `// BEGIN TASK n` and `// STARTER TASK n` (or
// `// END TASK n`) in labs/*/ is the answer the tests accept, and the handout gives students
// the starter instead. A slide shown in the lecture must not print it: it teaches the idea with
// the framework's own general function, pseudo-code or another example. Two checks:
// a shown code line inside a task block of the region itself, and an excerpt from anywhere
// (the framework, pong/) that repeats `answerLines` or more significant lines of one task's
// answer word for word (a copy of the answer under another name is still the answer).
const answerLines = 3;
// A line that says something: at least 12 characters of code (spaces and comments dropped),
// and more than a bare `return x;`, `break;` or a brace.
const normalisedCode = (line) => codeOfLine(line).replace(/\s+/g, '');
const significant = (code) => code.length >= 12 && !/^(return\w*|break|continue)?;?[{}]?;?$/.test(code) &&
  !/^return[\w.]*;$/.test(code);

function labFiles(root) {
  const labs = path.join(root, 'labs');
  if (!fs.existsSync(labs)) return [];
  return sourceFiles(root, 'labs');
}
// Every task's answer lines: [{where: "labs/..:line", label: "lab 05 task 4", lines: Set}].
function taskAnswerIndex(root) {
  const tasks = [];
  for (const file of labFiles(root)) {
    const lines = fs.readFileSync(path.join(root, file), 'utf8').split(/\r?\n/);
    let open = null;
    lines.forEach((line, index) => {
      if (taskBegin.test(line)) {
        const number = (line.match(/TASK\s*(\d+)/) || [])[1] ?? '?';
        open = { where: `${file}:${index + 1}`, label: `lab ${file.split('/')[1].slice(0, 2)} task ${number}`, lines: new Set() };
        tasks.push(open);
      } else if (taskStarter.test(line) || taskEnd.test(line)) open = null;
      else if (open && !commentLine(line)) {
        const code = normalisedCode(line);
        if (significant(code)) open.lines.add(code);
      }
    });
  }
  return tasks;
}
function answerProblems(solution, parts, file, taskIndex, shownCode) {
  const problems = [];
  const inside = new Set();
  for (const [first, last] of parts)
    for (let l = first; l <= last; l++) {
      const line = solution[l - 1];
      if (line && line.task && line.text.trim() !== '' && !commentLine(line.text)) inside.add(line.task);
    }
  for (const task of inside)
    problems.push(`shows the answer to ${file}'s ${task.toLowerCase()}: a lecture slide must not hand students a graded ` +
      'answer (teach the idea with the framework\'s general function, pseudo-code or another example)');
  if (inside.size) return problems;
  const shown = new Set(shownCode.map(normalisedCode).filter(significant));
  for (const task of taskIndex ?? []) {
    const same = [...task.lines].filter((l) => shown.has(l));
    if (same.length >= answerLines)
      problems.push(`repeats ${same.length} lines of the answer to ${task.label} (${task.where}) word for word: a lecture ` +
        'slide must not hand students a graded answer (teach it with pseudo-code or another example)');
  }
  return problems;
}

// --- A reader can follow an excerpt --------------------------------------------------------
// A name the excerpt uses must be declared where the reader can see it: in the excerpt, in an
// earlier excerpt of the same region in this deck, or outside the region (a parameter, a
// member), or named in backticks in the slide's caption or notes, which say what it is. A
// local declared in the lines the excerpt leaves out (`sharedMidX` computed in the gap,
// `inside` declared above the loop) and explained nowhere leaves the reader guessing.
const notTypes = new Set(['return', 'else', 'case', 'goto', 'delete', 'throw', 'using', 'typedef', 'new', 'co_return', 'not', 'and', 'or']);
function declaredName(line) {
  const m = codeOfLine(line).match(/^(?:(?:const|constexpr|static|auto)\s+)*([A-Za-z_][\w:<>,]*)[\s&*]+([A-Za-z_]\w*)\s*(?:=|;|\{|\[)/);
  return m && !notTypes.has(m[1]) ? m[2] : null;
}
function undeclaredNames(code, parts, shownBefore, explained) {
  if (parts.length === 1 && parts[0][0] === 1 && parts[0][1] === code.length) return [];
  const visible = new Set();
  for (const [first, last] of [...parts, ...shownBefore.map((s) => [s.first, s.last])])
    for (let l = first; l <= last; l++) visible.add(l);
  const declaredHidden = new Map();
  const declaredShown = new Set();
  code.forEach((line, index) => {
    const name = declaredName(line);
    if (!name) return;
    if (visible.has(index + 1)) declaredShown.add(name);
    else if (!declaredHidden.has(name)) declaredHidden.set(name, index + 1);
  });
  const problems = [];
  for (const [name, line] of declaredHidden) {
    if (declaredShown.has(name) || explained.has(name)) continue;
    const use = new RegExp(`(?<![\\w.>:])${name}\\b`);
    const usedAt = parts.flatMap(([first, last]) => code.slice(first - 1, last)).find((l) => use.test(codeOfLine(l)));
    if (usedAt) problems.push(`uses ${name}, declared at line ${line} of the region, which the slide does not show: "${usedAt.trim()}"`);
  }
  return problems;
}

// --- One deck says a thing once ------------------------------------------------------------
// Two excerpts of one deck may not show the same code twice (the same region's lines are
// checked by range; this catches two regions holding the same lines, such as two labs'
// answers): `answerLines` significant lines in common fail.
function repeatedElsewhere(code, name, shownCode) {
  const mine = new Set(code.map(normalisedCode).filter(significant));
  const problems = [];
  for (const other of shownCode) {
    if (other.name === name) continue;
    const same = other.lines.map(normalisedCode).filter((l) => mine.has(l));
    if (new Set(same).size >= answerLines)
      problems.push(`repeats ${new Set(same).size} lines already shown at ${other.where} (${other.name}): say it once`);
  }
  return problems;
}

function dedentTagged(tagged) {
  const texts = dedent(tagged.map((l) => l.text));
  const firstKept = tagged.findIndex((l) => l.text.trim() !== '');
  return texts.map((text, i) => ({ text, task: tagged[firstKept + i].task }));
}

class RegionIndex {
  constructor(root) {
    this.root = root;
    this.byFile = new Map();
    this.allFiles = null;
  }
  regionsIn(file) {
    if (!this.byFile.has(file)) this.byFile.set(file, regionsOf(this.root, file));
    return this.byFile.get(file);
  }
  // {file, region} or {error}
  find(file, name) {
    if (file) {
      if (!fs.existsSync(path.join(this.root, file))) return { error: `region ${name} not found in ${file} (no such file)` };
      const region = this.regionsIn(file).get(name);
      return region ? { file, region } : { error: `region ${name} not found in ${file}` };
    }
    if (!this.allFiles) this.allFiles = sourceFiles(this.root);
    const matches = this.allFiles.filter((f) => this.regionsIn(f).has(name));
    if (matches.length === 0) return { error: `region ${name} not found in the project's sources` };
    if (matches.length > 1) return { error: `region ${name} is defined in ${matches.join(' and ')}: name the file` };
    return { file: matches[0], region: this.regionsIn(matches[0]).get(name) };
  }
}

// The `names` in backticks that each line's slide explains in its caption or notes.
function explainedNames(lines) {
  const result = [];
  let start = 0;
  for (let i = 0; i <= lines.length; i++) {
    if (i === lines.length || lines[i] === '---') {
      const text = lines.slice(start, i).join('\n');
      const names = new Set([...text.matchAll(/`([A-Za-z_]\w*)`/g)].map((m) => m[1]));
      for (let k = start; k < i; k++) result[k] = names;
      start = i + 1;
      result[i] = new Set();
    }
  }
  return result;
}

function processDeck(deckPath, deckLabel, index, options, problems, listing) {
  const lines = fs.readFileSync(deckPath, 'utf8').split(/\r?\n/);
  const explained = explainedNames(lines);
  const output = [];
  lines.forEach((line, i) => {
    const match = line.match(includeLine);
    if (!match) {
      output.push(line);
      return;
    }
    const [, file, name, ranges, key] = match;
    const where = `${deckLabel}:${i + 1}`;
    const found = index.find(file, name);
    if (found.error) {
      problems.push(`${where}: ${found.error}`);
      output.push('```text', `MISSING CODE: region ${name}`, `(${found.error})`, '```');
      return;
    }
    let code = dedent(withoutTaskMarkers(found.region.lines));
    const partList = ranges ? [] : [[1, code.length]];
    if (ranges) {
      if (!key) {
        problems.push(`${where}: part of region ${name} (lines ${ranges}) needs key "TEXT": the line the slide is about`);
        return;
      }
      const parts = [];
      let previous = 0;
      for (const range of ranges.split(',')) {
        const bounds = range.trim().match(/^(\d+)-(\d+)$/);
        const first = bounds ? Number(bounds[1]) : 0;
        const last = bounds ? Number(bounds[2]) : 0;
        if (!bounds || first < 1 || last < first || last > code.length || first <= previous) {
          problems.push(`${where}: lines ${ranges} outside region ${name} (${code.length} lines) or out of order`);
          return;
        }
        partList.push([first, last]);
        // The gap, marked `// ...` when it leaves out code: a gap of comments alone is not
        // "code left out", and a reader would look for the missing statements.
        const gap = code.slice(previous, first - 1);
        if (previous && gap.some((l) => !/^\s*(\/\/.*)?$/.test(l))) parts.push(null);
        for (let l = first; l <= last; l++) parts.push(code[l - 1]);
        previous = last;
      }
      const kept = dedent(parts.map((l) => (l === null ? '' : l)));
      code = [];
      const indentOf = (l) => (l.match(/^[ \t]*/) || [''])[0];
      // Dedent lost the gap markers' indentation: give each the indentation of the next line,
      // or of the line before when the next one closes a block (the gap is inside it).
      let k = 0;
      for (let p = 0; p < parts.length; p++) code.push(kept[k++] ?? '');
      const gapIndent = (p) => (/^\s*\}/.test(code[p + 1] || '') ? indentOf(code[p - 1] || '') : indentOf(code[p + 1] || ''));
      code = code.map((l, p) => (parts[p] === null ? `${gapIndent(p)}// ...` : l));
      code = dedent(code);
    }
    const cut = wholeProblems(dedent(withoutTaskMarkers(found.region.lines)), partList, found.region);
    if (cut.length) {
      for (const problem of cut) problems.push(`${where}: the excerpt of ${name} ${problem}`);
      return;
    }
    const solution = dedentTagged(taggedSolution(found.region.lines));
    const answers = answerProblems(solution, partList, found.file, options.taskIndex, code);
    const undeclared = undeclaredNames(solution.map((l) => l.text), partList, options.shownLines.get(name) ?? [], explained[i]);
    const repeated = repeatedElsewhere(code, name, options.shownCode);
    for (const problem of [...answers, ...undeclared, ...repeated]) problems.push(`${where}: the excerpt of ${name} ${problem}`);
    options.shownCode.push({ name, where, lines: code });
    const shown = options.shownLines.get(name) ?? [];
    for (const [first, last] of partList) {
      const again = shown.find((s) => first <= s.last && s.first <= last);
      if (again)
        problems.push(`${where}: the excerpt of ${name} repeats lines ${Math.max(first, again.first)}-${Math.min(last, again.last)} already shown at ${again.where}`);
      shown.push({ first, last, where });
    }
    options.shownLines.set(name, shown);
    if (key && !code.some((l) => l.includes(key))) {
      problems.push(`${where}: the excerpt of ${name} does not contain its key line "${key}" (cut too early?)`);
      return;
    }
    const inBody = shownInBody(found.file, withoutTaskMarkers(found.region.lines), partList);
    code = fitToSlide(code, languageOf(found.file), options.styleFolder, inBody);
    if (code.length > maxLinesPerSlide)
      console.warn(`${where}: warning: region ${name} shows ${code.length} lines (more than ${maxLinesPerSlide} fit a slide)`);
    listing.push(`${where} ${name} ${found.file}:${found.region.startLine}`);
    output.push('```' + languageOf(found.file), ...code, '```');
  });
  if (options.out) fs.writeFileSync(path.join(options.out, path.basename(deckPath)), output.join('\n'));
}

function main() {
  const options = parseArguments(process.argv.slice(2));
  const index = new RegionIndex(options.root);
  options.styleFolder = slideStyleFolder(options.root);
  options.taskIndex = taskAnswerIndex(options.root);
  const decks = fs.readdirSync(options.src).filter((f) => f.endsWith('.md')).sort();
  if (options.out) fs.mkdirSync(options.out, { recursive: true });
  const problems = [];
  const listing = [];
  for (const deck of decks) {
    options.shownLines = new Map(); // region -> the line ranges this deck has shown
    options.shownCode = []; // every excerpt this deck has shown: {name, where, lines}
    const deckPath = path.join(options.src, deck);
    processDeck(deckPath, path.relative(process.cwd(), deckPath), index, options, problems, listing);
  }
  fs.rmSync(options.styleFolder, { recursive: true, force: true });
  if (options.list) console.log(listing.join('\n'));
  for (const problem of problems) console.error(problem);
  if (problems.length && !options.allowMissing) {
    console.error(`include-regions: ${problems.length} problem(s) (missing regions, excerpts not whole)`);
    process.exit(1);
  }
  console.error(`include-regions: ${decks.length} deck(s), ${listing.length} region(s) included` +
    (problems.length ? `, ${problems.length} missing (placeholders)` : ''));
}

try {
  main();
} catch (error) {
  console.error(`include-regions: ${error.message}`);
  process.exit(1);
}
