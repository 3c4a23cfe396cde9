// Everything in the fixed-point library; include the single headers where only one is needed.
#pragma once

#include <fixedpoint/atan2.hpp>
#include <fixedpoint/convert.hpp>
#include <fixedpoint/iir.hpp>
#include <fixedpoint/q.hpp>
#include <fixedpoint/sincos.hpp>
#include <fixedpoint/sqrt.hpp>
#include <fixedpoint/wide.hpp>
