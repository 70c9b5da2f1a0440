/* File checks the tests share: does a file exist, and did a writer leave
 * temporary files behind (ours are ".<name>.tmp-<pid>", OpenEXR's own
 * "tmp.<pid><name>"). */
#ifndef GTLAB_TESTS_TEST_FILES_H
#define GTLAB_TESTS_TEST_FILES_H

#include <dirent.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

/* Writes text to path; 0, or -1 if the file cannot be opened. */
static inline int write_text_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fputs(text, f);
    return fclose(f) == 0 ? 0 : -1;
}

static inline int file_exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

/* The number of leftover temporary files in dir, or -1 if it cannot be read. */
static inline int leftover_temp_files_in(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int count = 0;
    for (struct dirent *entry; (entry = readdir(d));)
        if (strstr(entry->d_name, ".tmp-") || strncmp(entry->d_name, "tmp.", 4) == 0)
            ++count;
    closedir(d);
    return count;
}

#endif
