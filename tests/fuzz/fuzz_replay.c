/* The fuzz targets outside libFuzzer (fuzz_target.h): every file named on
 * the command line, or inside a folder named there, runs once through
 * LLVMFuzzerTestOneInput, from a buffer of exactly its size (so the
 * sanitizers of the ASan build see any read past it). A crash or a failed
 * property fails the test; a folder that does not exist holds no input.
 * Prints how many inputs ran. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz_target.h"

int LLVMFuzzerInitialize(int *argc, char ***argv) __attribute__((weak));

/* Runs one file; returns 0, or -1 when it cannot be read. */
static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    fseek(f, 0, SEEK_END);
    const long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    uint8_t *data = malloc(size > 0 ? (size_t)size : 1);
    const int ok = data && size >= 0 && fread(data, 1, (size_t)size, f) == (size_t)size;
    fclose(f);
    if (ok)
        LLVMFuzzerTestOneInput(data, (size_t)size);
    free(data);
    return ok ? 0 : -1;
}

/* Runs every regular file in the folder; adds their number to *count. */
static int run_folder(const char *folder, int *count)
{
    DIR *d = opendir(folder);
    if (!d)
        return 0;
    int rc = 0;
    for (struct dirent *entry; rc == 0 && (entry = readdir(d)) != NULL;) {
        char path[4096];
        struct stat st;
        snprintf(path, sizeof path, "%s/%s", folder, entry->d_name);
        if (entry->d_name[0] == '.' || stat(path, &st) != 0 || !S_ISREG(st.st_mode))
            continue;
        rc = run_file(path);
        *count += rc == 0;
        if (rc != 0)
            fprintf(stderr, "cannot read %s\n", path);
    }
    closedir(d);
    return rc;
}

int main(int argc, char **argv)
{
    if (LLVMFuzzerInitialize)
        LLVMFuzzerInitialize(&argc, &argv);
    int count = 0;
    for (int i = 1; i < argc; ++i) {
        struct stat st;
        if (stat(argv[i], &st) != 0)
            continue;
        if (S_ISDIR(st.st_mode) ? run_folder(argv[i], &count) != 0 : run_file(argv[i]) != 0)
            return 1;
        count += !S_ISDIR(st.st_mode);
    }
    printf("%s: %d inputs, no crash\n", argv[0], count);
    return count > 0 ? 0 : 1;
}
