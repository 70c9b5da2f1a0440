RWStructuredBuffer<float> o;
float main(uint x) o[x]
