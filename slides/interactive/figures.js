// figures.js - the interactive figures in the decks: drag a shape, Hitbox answers.
//
// Every answer (hit or not, push-out, squared distances, shadows, times) comes from Hitbox's
// own C++ geometry compiled to WebAssembly (slides/wasm/figures.cpp, loaded before this file
// as hitbox-geometry.js). This file only keeps the shapes' positions, asks, and draws.
//
// In a deck:  <div class="interactive" data-figure="boxes"></div>
// Each figure is an SVG in its own pixels (y down, as in Hitbox), 1160 x 540: the shapes on
// the left, the answer in large text on the right. A drag moves a shape in whole steps of
// `snap` pixels, so an edge can be hit exactly (the edge rule is the point of two figures);
// the arrow keys then move the shape last clicked by 1 pixel (Shift: 10), for a 1-pixel
// overlap or a graze.
// build.sh also runs this file in Node (tools/interactive-stills.mjs) to draw each figure's
// first state as the still picture the PDF shows.
(function () {
  'use strict';

  const width = 1160;
  const height = 540;
  const panelX = 700; // the answer text starts here
  const snap = 10;
  const border = 4; // the frame around the figure, inside its width x height

  // --- Asking the geometry -------------------------------------------------------------
  let geometry = null;
  let answerBuffer = 0;
  // Calls the exported C function `name` with the numbers and an answer buffer; returns the
  // answer as plain numbers (see figures.cpp for what each position means).
  function ask(name, numbers) {
    geometry['_' + name](...numbers, answerBuffer);
    return Array.from(geometry.HEAPF32.subarray(answerBuffer / 4, answerBuffer / 4 + 32));
  }

  // --- Drawing helpers (SVG as text, so Node can draw the stills too) ----------------------
  const colours = { a: '#1f6fd1', b: '#e07a10', hit: '#c62828', apart: '#2e7d32', ink: '#222' };
  // A slab time: beyond the line's reach (figures.cpp's lineReach) it is "for ever".
  function formatTime(value) {
    if (value <= -999) return '\u2212\u221e';
    if (value >= 999) return '+\u221e';
    return format(value);
  }

  function format(value) {
    const text = String(Number(value.toFixed(2)));
    return text.replace('-', '\u2212');
  }
  function rect(x, y, w, h, style) {
    return `<rect x="${x}" y="${y}" width="${w}" height="${h}" ${style}/>`;
  }
  function line(x1, y1, x2, y2, style) {
    return `<line x1="${x1}" y1="${y1}" x2="${x2}" y2="${y2}" ${style}/>`;
  }
  function circle(x, y, r, style) {
    return `<circle cx="${x}" cy="${y}" r="${r}" ${style}/>`;
  }
  function label(x, y, text, style = '') {
    return `<text x="${x}" y="${y}" ${style}>${text.replace(/</g, '&lt;')}</text>`; // stills are XML
  }
  function polygon(points, style) {
    const list = [];
    for (let i = 0; i < points.length; i += 2) list.push(`${points[i]},${points[i + 1]}`);
    return `<polygon points="${list.join(' ')}" ${style}/>`;
  }
  function arrow(x1, y1, x2, y2, colour) {
    return line(x1, y1, x2, y2, `stroke="${colour}" stroke-width="5" marker-end="url(#arrow-${colour.slice(1)})"`);
  }
  // A draggable shape gets data-handle: pointer events on it move that point of the state.
  const handleStyle = 'class="handle" fill="#fff" stroke="#222" stroke-width="3"';
  const tick = (yes) => (yes ? '\u2713' : '\u2717');
  // The answer panel: one line of large text a row.
  function panel(lines) {
    return rect(panelX - 20, 1, width - panelX + 19, height - 2, 'fill="#fff"') + lines
      .map(([text, colour], row) => label(panelX, 60 + row * 52, text, `class="answer" fill="${colour || colours.ink}"`))
      .join('');
  }
  function verdict(hit, hitText, apartText) {
    return [hit ? hitText : apartText, hit ? colours.hit : colours.apart];
  }

  // --- The figures ---------------------------------------------------------------------------
  // Each figure: `start` (its first state: points and numbers), `question(state)` (the C
  // function and the numbers it is asked with), `draw(state, answer)` (SVG text), and
  // optionally `drag(state, handle, to)` when a handle does more than move its point, and
  // `reach(state, handle)`: how far the dragged shape reaches around its point [left, right,
  // up, down], so that it stays whole in the drawing.
  const figures = {};

  // 1. Two boxes: the four comparisons, and the push-out when all four hold.
  figures.boxes = {
    start: { a: { x: 120, y: 120 }, b: { x: 300, y: 220 }, aSize: [220, 160], bSize: [240, 200] },
    question: (s) => ['boxesAnswer', [s.a.x, s.a.y, ...s.aSize, s.b.x, s.b.y, ...s.bSize]],
    reach: (s, handle) => [0, s[handle + 'Size'][0], 0, s[handle + 'Size'][1]],
    draw(s, answer) {
      const [aw, ah] = s.aSize;
      const [bw, bh] = s.bSize;
      const names = [
        `A.left ${s.a.x} < B.right ${s.b.x + bw}`,
        `B.left ${s.b.x} < A.right ${s.a.x + aw}`,
        `A.top ${s.a.y} < B.bottom ${s.b.y + bh}`,
        `B.top ${s.b.y} < A.bottom ${s.a.y + ah}`,
      ];
      const lines = names.map((name, i) => [`${tick(answer[i])} ${name}`, answer[i] ? colours.ink : colours.apart]);
      const hit = answer[4] === 1;
      lines.push(verdict(hit, 'all four: overlap', 'one fails: apart'));
      const push = [answer[5] * answer[7], answer[6] * answer[7]];
      if (hit) lines.push([`push A by (${format(push[0])}, ${format(push[1])})`, colours.hit]);
      let svg = rect(s.b.x, s.b.y, bw, bh, `fill="${colours.b}" fill-opacity="0.25" stroke="${colours.b}" stroke-width="4" data-handle="b" class="handle-body"`);
      svg += rect(s.a.x, s.a.y, aw, ah, `fill="${colours.a}" fill-opacity="0.25" stroke="${colours.a}" stroke-width="4" data-handle="a" class="handle-body"`);
      svg += label(s.a.x + 14, s.a.y + 44, 'A', `class="name" fill="${colours.a}"`);
      svg += label(s.b.x + bw - 44, s.b.y + bh - 16, 'B', `class="name" fill="${colours.b}"`);
      if (hit) {
        svg += rect(s.a.x + push[0], s.a.y + push[1], aw, ah, `fill="none" stroke="${colours.a}" stroke-width="3" stroke-dasharray="10 8"`);
        const cx = s.a.x + aw / 2;
        const cy = s.a.y + ah / 2;
        svg += arrow(cx, cy, cx + push[0], cy + push[1], colours.hit);
      }
      return svg + panel(lines);
    },
  };

  // 2. A point and a box: the edge rule (a point on an edge is outside).
  figures.pointInBox = {
    start: { p: { x: 200, y: 260 }, box: [200, 120, 320, 280] },
    question: (s) => ['pointInBoxAnswer', [s.p.x, s.p.y, ...s.box]],
    draw(s, answer) {
      const [left, top, w, h] = s.box;
      const names = [`left ${left} < x ${s.p.x}`, `x ${s.p.x} < right ${left + w}`,
        `top ${top} < y ${s.p.y}`, `y ${s.p.y} < bottom ${top + h}`];
      const lines = names.map((name, i) => [`${tick(answer[i])} ${name}`, answer[i] ? colours.ink : colours.apart]);
      const inside = answer[4] === 1;
      lines.push(verdict(inside, 'inside: a hit', 'outside: no hit'));
      lines.push(['on an edge = outside', colours.ink]);
      let svg = rect(left, top, w, h, `fill="${colours.b}" fill-opacity="0.2" stroke="${colours.b}" stroke-width="4"`);
      svg += line(s.p.x, 20, s.p.x, height - 20, 'stroke="#999" stroke-width="2" stroke-dasharray="6 6"');
      svg += line(20, s.p.y, panelX - 30, s.p.y, 'stroke="#999" stroke-width="2" stroke-dasharray="6 6"');
      svg += circle(s.p.x, s.p.y, 14, `fill="${inside ? colours.hit : colours.apart}" stroke="#222" stroke-width="3" data-handle="p"`);
      svg += label(s.p.x + 20, s.p.y - 18, 'P', `class="name" fill="${colours.ink}"`);
      return svg + panel(lines);
    },
  };

  // 3. Two circles: squared distance against the squared sum of the radii (no square root).
  figures.circles = {
    start: { a: { x: 200, y: 220 }, b: { x: 430, y: 320 }, radii: [90, 120] },
    question: (s) => ['circlesAnswer', [s.a.x, s.a.y, s.radii[0], s.b.x, s.b.y, s.radii[1]]],
    reach: (s, handle) => {
      const radius = s.radii[handle === 'a' ? 0 : 1];
      return [-radius, radius, -radius, radius];
    },
    draw(s, answer) {
      const [ra, rb] = s.radii;
      const hit = answer[2] === 1;
      const lines = [
        [`dx = ${format(s.a.x - s.b.x)},  dy = ${format(s.a.y - s.b.y)}`],
        [`d\u00b2 = dx\u00b2 + dy\u00b2 = ${format(answer[0])}`],
        [`(rA + rB)\u00b2 = ${ra + rb}\u00b2 = ${format(answer[1])}`],
        verdict(hit, 'd\u00b2 < (rA + rB)\u00b2: hit', 'd\u00b2 \u2265 (rA + rB)\u00b2: apart'),
      ];
      if (hit) lines.push([`depth ${format(answer[5])}`, colours.hit]);
      let svg = circle(s.b.x, s.b.y, rb, `fill="${colours.b}" fill-opacity="0.25" stroke="${colours.b}" stroke-width="4" data-handle="b" class="handle-body"`);
      svg += circle(s.a.x, s.a.y, ra, `fill="${colours.a}" fill-opacity="0.25" stroke="${colours.a}" stroke-width="4" data-handle="a" class="handle-body"`);
      svg += line(s.a.x, s.a.y, s.b.x, s.b.y, `stroke="${colours.ink}" stroke-width="3"`);
      svg += label((s.a.x + s.b.x) / 2 + 10, (s.a.y + s.b.y) / 2 - 10, 'd', `class="name" fill="${colours.ink}"`);
      svg += circle(s.a.x, s.a.y, 6, `fill="${colours.a}"`) + circle(s.b.x, s.b.y, 6, `fill="${colours.b}"`);
      svg += label(s.a.x - 12, s.a.y - 20, 'A', `class="name" fill="${colours.a}"`);
      svg += label(s.b.x - 12, s.b.y - 20, 'B', `class="name" fill="${colours.b}"`);
      return svg + panel(lines);
    },
  };

  // 4. SAT: two turned boxes and their shadows on the axis the search reports (the largest
  // gap when apart, the least overlap when they collide). Drag a box; drag its dot to turn it.
  const turnArm = 40; // the turning dot sits this far beyond the box's right edge
  figures.orientedBoxes = {
    start: { a: { x: 200, y: 170 }, b: { x: 450, y: 230 }, aHalf: [110, 55], bHalf: [80, 80], aAngle: 30, bAngle: -15 },
    question: (s) => ['orientedBoxesAnswer',
      [s.a.x, s.a.y, ...s.aHalf, s.aAngle, s.b.x, s.b.y, ...s.bHalf, s.bAngle]],
    reach: (s, handle) => {
      const corner = Math.hypot(...s[handle + 'Half']);
      return [-corner, corner, -corner, corner];
    },
    drag(s, handle, to) {
      if (handle !== 'aTurn' && handle !== 'bTurn') return false;
      const centre = handle === 'aTurn' ? s.a : s.b;
      const degrees = Math.round((Math.atan2(to.y - centre.y, to.x - centre.x) * 180) / Math.PI / 5) * 5;
      if (handle === 'aTurn') s.aAngle = degrees;
      else s.bAngle = degrees;
      return true;
    },
    draw(s, answer) {
      const apart = answer[0] === 1;
      const axis = [answer[1], answer[2]];
      const cornersA = answer.slice(4, 12);
      const cornersB = answer.slice(12, 20);
      const lines = [
        verdict(!apart, 'every axis overlaps: hit', 'a separating axis: apart'),
        [`axis (${format(axis[0])}, ${format(axis[1])})`],
        [`shadow A ${format(answer[20])} to ${format(answer[21])}`, colours.a],
        [`shadow B ${format(answer[22])} to ${format(answer[23])}`, colours.b],
        apart ? [`gap ${format(answer[3])}`, colours.apart] : [`least overlap ${format(-answer[3])}`, colours.hit],
        ['drag a dot to turn'],
      ];
      // The axis drawn as a line beside both boxes: a shadow point s lies at axis * s + side * offset.
      // The line lies beyond both boxes, below them (or left of them when the axis is upright).
      let side = [-axis[1], axis[0]];
      if (Math.abs(side[1]) > 0.3 ? side[1] < 0 : side[0] > 0) side = [-side[0], -side[1]];
      let offset = -Infinity;
      const all = cornersA.concat(cornersB);
      for (let i = 0; i < all.length; i += 2) offset = Math.max(offset, all[i] * side[0] + all[i + 1] * side[1]);
      offset += 50;
      const at = (along) => [axis[0] * along + side[0] * offset, axis[1] * along + side[1] * offset];
      let svg = `<clipPath id="sat-area"><rect x="0" y="0" width="${panelX - 20}" height="${height}"/></clipPath><g clip-path="url(#sat-area)">`;
      const far = [at(-2000), at(2000)];
      svg += line(far[0][0], far[0][1], far[1][0], far[1][1], 'stroke="#888" stroke-width="2"');
      [[answer[20], answer[21], colours.a, cornersA, -8], [answer[22], answer[23], colours.b, cornersB, 8]].forEach(
        ([low, high, colour, corners, shift]) => {
          const from = at(low);
          const to = at(high);
          svg += line(from[0] + side[0] * shift, from[1] + side[1] * shift, to[0] + side[0] * shift, to[1] + side[1] * shift,
            `stroke="${colour}" stroke-width="12" stroke-opacity="0.8"`);
          // Dashed lines from the corners that cast the shadow's two ends (nearest to them:
          // the geometry worked in float, this file in double).
          for (const end of [low, high]) {
            let best = 0;
            const distance = (i) => Math.abs(corners[i] * axis[0] + corners[i + 1] * axis[1] - end);
            for (let i = 2; i < corners.length; i += 2) if (distance(i) < distance(best)) best = i;
            const foot = at(end);
            svg += line(corners[best], corners[best + 1], foot[0], foot[1], `stroke="${colour}" stroke-width="2" stroke-dasharray="6 6"`);
          }
        });
      svg += '</g>';
      svg += polygon(cornersB, `fill="${colours.b}" fill-opacity="0.25" stroke="${colours.b}" stroke-width="4" data-handle="b" class="handle-body"`);
      svg += polygon(cornersA, `fill="${colours.a}" fill-opacity="0.25" stroke="${colours.a}" stroke-width="4" data-handle="a" class="handle-body"`);
      [['a', s.a, s.aHalf, s.aAngle, colours.a], ['b', s.b, s.bHalf, s.bAngle, colours.b]].forEach(([name, c, half, angle, colour]) => {
        const turn = (angle * Math.PI) / 180;
        const reach = half[0] + turnArm;
        const dot = [c.x + Math.cos(turn) * reach, c.y + Math.sin(turn) * reach];
        svg += line(c.x, c.y, dot[0], dot[1], `stroke="${colour}" stroke-width="3"`);
        svg += circle(dot[0], dot[1], 14, `${handleStyle} data-handle="${name}Turn"`);
        svg += label(c.x - 12, c.y + 12, name.toUpperCase(), `class="name" fill="${colour}"`);
      });
      return svg + panel(lines);
    },
  };

  // 5. A ray (one step's segment, start S to end E) against a box: the slab method's near
  // and far times, as fractions of the segment.
  figures.ray = {
    start: { s: { x: 60, y: 420 }, e: { x: 640, y: 80 }, box: [240, 160, 220, 180] },
    question: (s) => ['rayAnswer', [s.s.x, s.s.y, s.e.x, s.e.y, ...s.box]],
    draw(s, answer) {
      const [left, top, w, h] = s.box;
      const hit = answer[0] === 1;
      const lines = [verdict(hit, 'the ray hits the box', 'the ray misses')];
      const marks = [];
      if (hit) {
        lines.push([answer[2] ? `near t = ${format(answer[1])} (starts inside)` : `near t = ${format(answer[1])} (enters)`, colours.hit]);
        marks.push([answer[1], 'near']);
        if (answer[5] >= 0) {
          lines.push([`far t = ${format(answer[5])} (leaves)`, colours.ink]);
          marks.push([answer[5], 'far']);
        } else lines.push(['far: after E (t > 1)']);
      } else if (answer[6] === 1) {
        // The line through S and E crosses the box, but not between them.
        lines.push([`near t = ${format(answer[7])} (enters)`, colours.ink]);
        lines.push([`far t = ${format(answer[8])} (leaves)`, colours.ink]);
        lines.push(['both outside 0 to 1']);
        marks.push([answer[7], 'near'], [answer[8], 'far']);
      } else {
        // The line misses: the x slab's and the y slab's stretches of t do not overlap.
        const span = (inside, enter, exit) => (inside === 1 ? `t ${formatTime(enter)} to ${formatTime(exit)}` : 'never');
        lines.push([`x slab: ${span(answer[9], answer[10], answer[11])}`, colours.ink]);
        lines.push([`y slab: ${span(answer[12], answer[13], answer[14])}`, colours.ink]);
        lines.push(['no t inside both']);
      }
      lines.push(['S is t = 0, E is t = 1']);
      // The two slabs: the x band and the y band of the box. Inside both = inside the box.
      let svg = rect(left, 0, w, height, 'fill="#7b61ff" fill-opacity="0.08"');
      svg += rect(0, top, panelX - 20, h, 'fill="#7b61ff" fill-opacity="0.08"');
      svg += rect(left, top, w, h, `fill="${colours.b}" fill-opacity="0.25" stroke="${colours.b}" stroke-width="4"`);
      // On a miss whose line crosses the box: the line dashed on to where it leaves (or back
      // from where it enters), so near and far are seen on it.
      if (!hit && answer[6] === 1) {
        const at = (t) => [s.s.x + (s.e.x - s.s.x) * t, s.s.y + (s.e.y - s.s.y) * t];
        const from = at(Math.min(0, answer[7]));
        const to = at(Math.max(1, answer[8]));
        svg += line(from[0], from[1], to[0], to[1], `stroke="${colours.a}" stroke-width="2" stroke-dasharray="6 8" stroke-opacity="0.6"`);
      }
      svg += arrow(s.s.x, s.s.y, s.e.x, s.e.y, colours.a);
      for (const [t, name] of marks) {
        const x = s.s.x + (s.e.x - s.s.x) * t;
        const y = s.s.y + (s.e.y - s.s.y) * t;
        svg += circle(x, y, 10, `fill="${colours.hit}"`);
        svg += label(x + 16, y + (name === 'near' ? 36 : -16), name, `class="name small" fill="${colours.hit}"`);
      }
      svg += circle(s.s.x, s.s.y, 14, `${handleStyle} data-handle="s"`) + label(s.s.x - 40, s.s.y + 10, 'S', 'class="name"');
      svg += circle(s.e.x, s.e.y, 14, `${handleStyle} data-handle="e"`) + label(s.e.x + 20, s.e.y + 10, 'E', 'class="name"');
      return svg + panel(lines);
    },
  };

  // 6. A box swept against a wall: where along its move it first touches (time of impact).
  figures.sweptBox = {
    // The wall leaves room above and below it, so the box can pass a corner or graze it.
    start: { from: { x: 60, y: 220 }, to: { x: 560, y: 140 }, size: [90, 90], wall: [460, 120, 40, 300] },
    question: (s) => ['sweptBoxAnswer',
      [s.from.x, s.from.y, ...s.size, s.to.x - s.from.x, s.to.y - s.from.y, ...s.wall]],
    reach: (s) => [0, s.size[0], 0, s.size[1]],
    draw(s, answer) {
      const [w, h] = s.size;
      const hit = answer[0] === 1;
      const lines = [verdict(hit, 'hits the wall this step', 'no hit this step')];
      if (hit) {
        lines.push([answer[2] ? 'started inside: t = 0' : `time of impact t = ${format(answer[1])}`, colours.hit]);
        lines.push([`normal (${format(answer[3])}, ${format(answer[4])})`]);
      }
      lines.push(['drag the box or its end']);
      let svg = rect(...s.wall, `fill="#555" fill-opacity="0.35" stroke="#333" stroke-width="3"`);
      // The swept area: the lines joining the box's corners at the start and at the end.
      for (const [dx, dy] of [[0, 0], [w, 0], [0, h], [w, h]])
        svg += line(s.from.x + dx, s.from.y + dy, s.to.x + dx, s.to.y + dy, 'stroke="#999" stroke-width="2" stroke-dasharray="6 6"');
      svg += rect(s.to.x, s.to.y, w, h, `fill="none" stroke="${colours.a}" stroke-width="3" stroke-dasharray="10 8" data-handle="to" class="handle-body"`);
      svg += rect(s.from.x, s.from.y, w, h, `fill="${colours.a}" fill-opacity="0.25" stroke="${colours.a}" stroke-width="4" data-handle="from" class="handle-body"`);
      if (hit) {
        const x = s.from.x + (s.to.x - s.from.x) * answer[1];
        const y = s.from.y + (s.to.y - s.from.y) * answer[1];
        svg += rect(x, y, w, h, `fill="${colours.hit}" fill-opacity="0.3" stroke="${colours.hit}" stroke-width="4"`);
        // Above the box, ending at its right edge: clear of the wall it touches and of the box.
        svg += label(x + w, y - 20, `t = ${format(answer[1])}`, `class="name small" text-anchor="end" fill="${colours.hit}"`);
      }
      svg += label(s.from.x + 8, s.from.y + h + 36, 'start', 'class="name small"');
      svg += label(s.to.x + 8, s.to.y + h + 36, 'end', 'class="name small"');
      return svg + panel(lines);
    },
  };

  // --- The SVG around a figure -----------------------------------------------------------------
  const defs = ['#c62828', '#1f6fd1'].map((colour) =>
    `<marker id="arrow-${colour.slice(1)}" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="4" markerHeight="4" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="${colour}"/></marker>`).join('');
  const style = '<style>text{font-family:sans-serif}.answer{font-size:30px}.name{font-size:34px;font-weight:bold}' +
    '.name.small{font-size:26px}.handle,.handle-body{cursor:grab}' +
    // Only shapes with a handle take the pointer: labels and lines on top must not catch it.
    '*{pointer-events:none}[data-handle]{pointer-events:all}</style>';
  function render(name, state) {
    const figure = figures[name];
    const [functionName, numbers] = figure.question(state);
    const answer = ask(functionName, numbers);
    const svg = `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${width} ${height}" width="${width}" height="${height}">` +
      `<defs>${defs}</defs>${style}${rect(0, 0, width, height, 'fill="#fff"')}${figure.draw(state, answer)}` +
      // The border last, over the answer panel's white, and inside the picture: a stroke on
      // the picture's edge is half outside it, and the PDF loses its right and bottom sides.
      `${rect(border / 2, border / 2, width - border, height - border, `class="border" fill="none" stroke="#999" stroke-width="${border}"`)}</svg>`;
    return { svg, question: [functionName, ...numbers] };
  }

  // --- In the browser: draggable ------------------------------------------------------------------
  function attach(element) {
    const name = element.dataset.figure;
    const state = JSON.parse(JSON.stringify(figures[name].start));
    const live = document.createElement('div');
    live.className = 'live';
    element.prepend(live);
    let dragging = null; // { handle, last }
    let selected = null; // the handle the arrow keys move (the last one clicked)
    live.tabIndex = 0; // focusable: the arrow keys go to the figure, not to the slides
    function update() {
      const { svg, question } = render(name, state);
      live.innerHTML = svg;
      element.dataset.question = JSON.stringify(question); // for the test: what was asked
    }
    // Moves a handle's point; the shape stays whole inside the drawing, left of the answer.
    function moveBy(handle, dx, dy) {
      const point = state[handle];
      const [left, right, up, down] = figures[name].reach ? figures[name].reach(state, handle) : [0, 0, 0, 0];
      point.x = Math.min(Math.max(point.x + dx, 20 - left), panelX - 40 - right);
      point.y = Math.min(Math.max(point.y + dy, 20 - up), height - 20 - down);
    }
    const arrows = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
    live.addEventListener('keydown', (event) => {
      const step = arrows[event.key];
      // Only handles that are points move by keys (a turning handle is dragged).
      if (!step || selected === null || !(state[selected] && 'x' in state[selected])) return;
      const size = event.shiftKey ? snap : 1;
      moveBy(selected, step[0] * size, step[1] * size);
      update();
      event.preventDefault();
      event.stopPropagation(); // not the next slide
    });
    // Pointer position in the figure's own pixels, however the slide is scaled.
    function toFigure(event) {
      const box = live.firstChild.getBoundingClientRect();
      return { x: ((event.clientX - box.left) * width) / box.width, y: ((event.clientY - box.top) * height) / box.height };
    }
    live.addEventListener('pointerdown', (event) => {
      const handle = event.target.closest('[data-handle]');
      if (!handle) return;
      dragging = { handle: handle.dataset.handle, last: toFigure(event) };
      selected = handle.dataset.handle;
      live.focus({ preventScroll: true });
      live.setPointerCapture(event.pointerId);
      event.preventDefault();
      event.stopPropagation();
    });
    live.addEventListener('pointermove', (event) => {
      if (!dragging) return;
      const to = toFigure(event);
      if (!(figures[name].drag && figures[name].drag(state, dragging.handle, to))) {
        // Move the handle's point by whole steps of `snap` pixels.
        const dx = Math.round((to.x - dragging.last.x) / snap) * snap;
        const dy = Math.round((to.y - dragging.last.y) / snap) * snap;
        moveBy(dragging.handle, dx, dy);
        dragging.last = { x: dragging.last.x + dx, y: dragging.last.y + dy };
      }
      update();
      event.stopPropagation();
    });
    const stop = (event) => {
      dragging = null;
      event.stopPropagation();
    };
    live.addEventListener('pointerup', stop);
    live.addEventListener('pointercancel', stop);
    update();
  }

  const api = { figures, render, format };
  if (typeof document !== 'undefined' && typeof HitboxGeometry === 'function') {
    const loaded = new Promise((resolve) =>
      document.readyState === 'loading' ? document.addEventListener('DOMContentLoaded', resolve) : resolve());
    Promise.all([HitboxGeometry(), loaded]).then(([module]) => {
      api.use(module);
      document.querySelectorAll('.interactive[data-figure]').forEach(attach);
      document.documentElement.dataset.figuresReady = 'yes'; // the test waits for this
    });
  }
  // In Node (the stills): the caller hands over the module.
  api.use = (module) => {
    geometry = module;
    answerBuffer = geometry._malloc(32 * 4);
  };
  if (typeof globalThis !== 'undefined') globalThis.HitboxFigures = api;
})();
