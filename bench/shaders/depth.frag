#version 450 core
// Depth prepass and probe: no colour, no lookup.
void main() {}
