int stray(void) { return 1; }
