#include "core/threads.h"

#include <omp.h>

int threads_default(void) { return omp_get_num_procs(); }

void threads_set(int count) { omp_set_num_threads(count); }
