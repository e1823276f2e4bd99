// Marp CLI settings shared by build.sh and check.sh.
export default {
  // The PDF decks carry their images as data: URLs (tools/inline-images.mjs), and markdown-it
  // refuses an SVG one unless told: the build's own images in base64 are allowed.
  engine: ({ marp }) => {
    const usual = marp.markdown.validateLink;
    marp.markdown.validateLink = (url) => /^data:image\/(svg\+xml|png|apng);base64,/i.test(url.trim()) || usual(url);
    return marp;
  },
  // Decks may use a little HTML (two-column layouts, the benchmark placeholder).
  html: true,
  themeSet: ['./theme/hitbox.css'],
  options: {
    // MathJax renders formulas as inline SVG: the HTML works offline (KaTeX needs a CDN).
    math: 'mathjax',
    // Twemoji would load pictures from the network: keep every character as text.
    emoji: { shortcode: false, unicode: false },
    // A line break in the Markdown source is a space, as in any Markdown: sentences can be
    // wrapped in the source without breaking the line on the slide.
    markdown: { breaks: false },
  },
};
