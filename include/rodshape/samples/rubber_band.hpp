// The paper's rubber band as a sample model (Sec. V): L = 0.29 m, a 0.02 × 0.02 m section of
// natural rubber (E = 3.2 MPa, ν = 0.5, ρ = 1392 kg/m³), with the identified bending and torsional
// stiffness EIx = EIy = 0.04 N·m², GJ = 0.028 N·m² in place of E·I and G·J. Clamped at the origin,
// tangent along +z, weightless (the paper neglects gravity). The benchmarks, the tests and the
// consumer example use it; examples/rubber_band.yaml is the same rod as a task file.
#pragma once

#include "rodshape/core/clamped_rod.hpp"
#include "rodshape/core/pose.hpp"
#include "rodshape/core/rod_properties.hpp"

namespace rodshape::samples {

/// The band as a user describes it: length, section, material and identified stiffnesses.
RodDescription rubber_band_description(ConstitutiveModel model = ConstitutiveModel::Cosserat);

/// The band clamped at the origin with `intervals` integration intervals (validated).
ClampedRod rubber_band(ConstitutiveModel model = ConstitutiveModel::Cosserat, int intervals = 100);

/// The bundled example's held tip (examples/rubber_band.yaml): 0.12 m aside, 0.22 m up, turned 90°
/// about y.
Pose bent_tip();

}  // namespace rodshape::samples
