/* The run's inputs by identity; see run_inputs.h. */
#define _DEFAULT_SOURCE /* realpath */
#include "core/files/run_inputs.h"

#include <dirent.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

enum { MAX_INPUTS = 1024, GIVEN_MAX = 160 };

typedef struct {
    dev_t dev;
    ino_t ino;
    char given_as[GIVEN_MAX]; /* "--data ./mb.exr" */
    char *resolved;           /* realpath of the file, for run_inputs_check_folder (malloc'd) */
} run_input;

static run_input inputs[MAX_INPUTS];
static int input_count;
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

static int noted_index(dev_t dev, ino_t ino)
{
    for (int i = 0; i < input_count; ++i)
        if (inputs[i].dev == dev && inputs[i].ino == ino)
            return i;
    return -1;
}

void run_inputs_note(const char *path, const char *given_as)
{
    struct stat st;
    if (!path || !*path || stat(path, &st) != 0 || S_ISDIR(st.st_mode))
        return;
    pthread_mutex_lock(&lock);
    if (noted_index(st.st_dev, st.st_ino) < 0 && input_count < MAX_INPUTS) {
        run_input *r = &inputs[input_count++];
        r->dev = st.st_dev, r->ino = st.st_ino;
        snprintf(r->given_as, sizeof r->given_as, "%s%s%s", given_as ? given_as : "", given_as ? " " : "", path);
        r->resolved = realpath(path, NULL);
    }
    pthread_mutex_unlock(&lock);
}

void run_inputs_note_folder(const char *dir, const char *given_as)
{
    DIR *d = dir ? opendir(dir) : NULL;
    if (!d)
        return;
    for (struct dirent *entry; (entry = readdir(d));) {
        char path[PATH_MAX];
        if (entry->d_name[0] != '.' && snprintf(path, sizeof path, "%s/%s", dir, entry->d_name) < (int)sizeof path)
            run_inputs_note(path, given_as);
    }
    closedir(d);
}

int run_inputs_check_output(const char *path, gt_error *e)
{
    struct stat st;
    if (!path || stat(path, &st) != 0)
        return 0;
    pthread_mutex_lock(&lock);
    int i = noted_index(st.st_dev, st.st_ino);
    char given_as[GIVEN_MAX];
    if (i >= 0)
        snprintf(given_as, sizeof given_as, "%s", inputs[i].given_as);
    pthread_mutex_unlock(&lock);
    if (i < 0)
        return 0;
    return gt_error_set(e, path, "is also an input of this run (%s); refusing to overwrite it", given_as);
}

int run_inputs_check_folder(const char *dir, const char *what, gt_error *e)
{
    char *folder = realpath(dir, NULL); /* a folder that does not exist holds no input */
    if (!folder)
        return 0;
    size_t n = strlen(folder);
    int found = -1;
    pthread_mutex_lock(&lock);
    for (int i = 0; i < input_count && found < 0; ++i) {
        const char *r = inputs[i].resolved;
        if (r && strncmp(r, folder, n) == 0 && (r[n] == '/' || (n == 1 && folder[0] == '/')))
            found = i;
    }
    char given_as[GIVEN_MAX];
    if (found >= 0)
        snprintf(given_as, sizeof given_as, "%s", inputs[found].given_as);
    pthread_mutex_unlock(&lock);
    free(folder);
    if (found < 0)
        return 0;
    return gt_error_set(e, dir, "holds an input of this run (%s), and %s; refusing to risk overwriting it: "
                        "move the input or choose another output folder", given_as, what);
}

void run_inputs_forget(void)
{
    pthread_mutex_lock(&lock);
    for (int i = 0; i < input_count; ++i)
        free(inputs[i].resolved);
    input_count = 0;
    pthread_mutex_unlock(&lock);
}
