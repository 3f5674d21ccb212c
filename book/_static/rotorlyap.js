// Every figure of the book opens at full size when clicked or tapped: its image becomes a link to
// the image file. A multi-panel figure shrunk to a phone's column (390 px) is then read in a tab
// of its own, at the resolution it was saved at (tests/browser/test_html.py checks every figure).
document.addEventListener("DOMContentLoaded", () => {
  for (const img of document.querySelectorAll("article figure img, article div.figure img")) {
    if (img.closest("a")) continue;
    const link = document.createElement("a");
    link.href = img.getAttribute("src");
    link.className = "rotorlyap-enlarge";
    link.title = "Open the figure at full size";
    img.replaceWith(link);
    link.appendChild(img);
  }
});
