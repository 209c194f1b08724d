// The declaration of each command (command_declaration.h), one file each:
// NAME_declaration.cpp. A new experiment adds its function here and to the list of
// commandDeclarations() (command_declaration.cpp).
#pragma once

#include "lamina/experiments/command_declaration.h"

namespace lamina::experiments {

CommandDecl renderDeclaration();        // render_declaration.cpp
CommandDecl compareDeclaration();       // compare_declaration.cpp
CommandDecl reciprocityDeclaration();   // reciprocity_declaration.cpp
CommandDecl convergenceDeclaration();   // convergence_declaration.cpp
CommandDecl fresnelDeclaration();       // fresnel_declaration.cpp
CommandDecl stabilityDeclaration();     // stability_declaration.cpp
CommandDecl layeringDeclaration();      // layering_declaration.cpp
CommandDecl polarisationDeclaration();  // polarisation_declaration.cpp
CommandDecl mediaDeclaration();         // media_declaration.cpp

}  // namespace lamina::experiments
