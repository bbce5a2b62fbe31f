#version 450 core
// Depth-only passes (shadow map, depth prepass, empty miss pass): no colour output.
void main() {}
