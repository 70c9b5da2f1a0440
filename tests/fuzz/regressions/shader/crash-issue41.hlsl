// gtlab.output ao.V
RWStructuredBuffer<float> o : register(u0);
[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) o[id.x] = 1;
