float y;
void main(uint x) y = 1;
