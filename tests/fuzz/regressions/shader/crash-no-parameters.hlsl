RWStructuredBuffer<float> o;
void main() o[1] = 1;
