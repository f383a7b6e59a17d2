#version 450 core
// Light volumes, stencil pass: writes no colour. Back faces behind the scene
// increment the stencil and front faces behind it decrement it, so pixels whose
// surface lies inside the sphere end up non-zero.
void main() {}
