#version 450 core
// Depth prepass / probe: no colour.
void main() {}
