RWStructuredBuffer<float> o : register(u0);
[numthreads(8, 1, 1)]
void main(uint3 id : SV_DispatchThreadID)
{
    o[id.x] = 2.0 * id.x;
}
