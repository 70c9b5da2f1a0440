RWTexture2D<float> t;
void main(uint2 x) t[x] = 1;
