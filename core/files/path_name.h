/* The file-name part of a path: what follows its last '/' (the whole path
 * when it has none). Names in tables, messages and checkpoints use it. */
#ifndef GTLAB_CORE_FILES_PATH_NAME_H
#define GTLAB_CORE_FILES_PATH_NAME_H

#include <string.h>

static inline const char *path_file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

#endif
