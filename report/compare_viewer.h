/* The report's image-comparison view: a set of images of one view (a
 * reference, approximations, their error maps) shown one at a time with
 * buttons, a click on the image or the keys 1-9, n/space and p/backspace to
 * flip between them, or side by side ('s'); the wheel zooms about the
 * pointer and dragging pans, the same transform on every image (so
 * flipping and side by side compare the same pixels, unsmoothed); 0 resets.
 * An exposure slider scales linear radiance by 2^EV on the (sRGB-encoded)
 * previews: decoded with gamma 2.2, scaled, encoded again (an SVG filter),
 * since 8-bit previews cannot hold more than what they clipped.
 *
 * Plain HTML with one small script and style written into report.html's
 * head by the writer: no network resource, works from file://. */
#ifndef GTLAB_REPORT_COMPARE_VIEWER_H
#define GTLAB_REPORT_COMPARE_VIEWER_H

/* The <style> and <script> elements (static text). */
const char *compare_viewer_head(void);

#endif
