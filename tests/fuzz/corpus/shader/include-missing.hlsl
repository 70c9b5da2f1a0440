#include "nowhere.inc"
[numthreads(1, 1, 1)]
void main() {}
