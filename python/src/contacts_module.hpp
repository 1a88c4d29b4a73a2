// The contact and distance calls of obbsat._core (contacts_module.cpp), kept
// in their own file so that the module's collide calls and these grow apart.
#pragma once

#include <obbsat/contact_manifold.hpp>

#include <pybind11/pybind11.h>

#include <cstddef>

/// Adds contacts_of_pairs, contacts_of_stream, distances_of_pairs,
/// distances_of_stream, find_contacts and their float64 calls (*64) to the module `m`.
void register_contacts(pybind11::module_& m);

/// The columns of `count` contacts as find_contacts returns them (a dict of
/// numpy arrays); call with the GIL held: the columns are filled without it.
pybind11::dict contact_dict(const obbsat::contact* contacts, std::size_t count);

/// The same columns in float64 for double contacts.
pybind11::dict contact_dict(const obbsat::contact64* contacts, std::size_t count);
