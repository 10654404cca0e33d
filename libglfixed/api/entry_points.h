// The one table of GL entry points, by name: serves OSMesaGetProcAddress (and
// glXGetProcAddress later). Every GL 1.0-2.1 command is exported; a command
// the library does not implement yet is a stub that records
// GL_INVALID_OPERATION, and its name resolves to null here.
#pragma once

namespace glfixed::api {

void* procAddress(const char* name);

// An ARB/EXT name of an implemented command (gl_arb_aliases.cpp), or null.
void* extensionAliasAddress(const char* name);

// True if `name` is a GL command this library implements.
bool isImplemented(const char* name);

}  // namespace glfixed::api
