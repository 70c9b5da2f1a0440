/* Text written into report.html from a stream; see html_text.h. */
#include "report/html_text.h"

void html_put_escaped(FILE *f, const char *text)
{
    for (const char *c = text; *c; ++c)
        switch (*c) {
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '&': fputs("&amp;", f); break;
        case '"': fputs("&quot;", f); break;
        default: fputc(*c, f);
        }
}
