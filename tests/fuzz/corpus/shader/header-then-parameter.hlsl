RWStructuredBuffer<float> o;
void main(uint x) x;
