// gtlab.output ao.V
RWStructuredBuffer<float> o : register(u0);
[numthreads(8, 8, 1)]
void main()
