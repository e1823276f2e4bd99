// marp-directives.mjs - which HTML comments in a deck are Marp directives, not speaker notes.
//
// One rule for every tool that reads the notes (check-decks.mjs checks them, deck-extras.mjs
// prints them in the notes PDF): a comment is a directive when it starts with one of Marp's
// directive names and a colon (`<!-- _class: lead -->`, `<!-- paginate: false -->`). Any other
// comment is a speaker note, also one that starts with a scoped name such as
// `hitbox::elasticCollision (Response.h) is ...` or with "Next:", as Marp's presenter view has it.
const directive = /^\s*_?(class|paginate|header|footer|theme|style|size|math|headingDivider|backgroundColor|backgroundImage|backgroundPosition|backgroundRepeat|backgroundSize|color|marp|title|description|author|image|keywords|url|transition|lang)\s*:/;

export function isDirective(comment) {
  return directive.test(comment);
}
