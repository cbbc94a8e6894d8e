/**
 * @file vtkRiemannNewArray.h
 * @brief The output arrays of the RiemannVTK filters: named, sized, ready to
 * be filled with SetValue/SetTypedTuple.
 *
 * A private header of Riemann::CommonCore (not wrapped, not installed): the
 * filters' .cxx files include it.
 */
#ifndef vtkRiemannNewArray_h
#define vtkRiemannNewArray_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

/// A new `Array` (vtkDoubleArray, vtkIntArray, ...) called `name`, of
/// `components` components and `tuples` tuples (values not set).
template <class Array>
vtkSmartPointer<Array> vtkRiemannNewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

#endif
