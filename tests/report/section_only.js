/* Shows one section of report.html alone, for a screenshot of it
 * (test_report_browser.sh): the page's query names the section's heading id
 * (report.html?claims-of-the-talks); every child of the body from the
 * heading up to the next h2 stays, the rest is hidden. (A #fragment would
 * scroll, and headless Chromium's screenshot of a scrolled page is blank.) */
(function () {
  var heading = document.getElementById(decodeURIComponent(location.search.slice(1)));
  var shown = false;
  for (var node = document.body.firstElementChild; node; node = node.nextElementSibling) {
    if (node === heading)
      shown = true;
    else if (shown && node.tagName === 'H2')
      shown = false;
    if (node.tagName !== 'SCRIPT')
      node.style.display = shown ? '' : 'none';
  }
  if (!heading)
    console.error('GTLAB-CHECK: no section ' + location.search);
})();
