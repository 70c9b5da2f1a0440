/* Text written into report.html from a stream (the summary table, the
 * resolved figures): the characters HTML gives a meaning to escaped. */
#ifndef GTLAB_REPORT_HTML_TEXT_H
#define GTLAB_REPORT_HTML_TEXT_H

#include <stdio.h>

/* text with <, >, & and " written as entities. */
void html_put_escaped(FILE *f, const char *text);

#endif
