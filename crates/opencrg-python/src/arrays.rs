//! Python inputs to slices and results back: two coordinates given as scalars or
//! array-likes of any shape are broadcast together and read as contiguous, aligned float64; the
//! results take their shape, or are Python floats when both inputs were scalars.

use numpy::{PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// Two broadcast coordinate arrays, borrowed for reading.
pub(crate) struct Pair<'py> {
    a: PyReadonlyArrayDyn<'py, f64>,
    b: PyReadonlyArrayDyn<'py, f64>,
    shape: Vec<usize>,
    scalar: bool,
}

impl<'py> Pair<'py> {
    /// Reads two coordinates (numbers, sequences or arrays of any numeric type).
    pub(crate) fn new(a: &Bound<'py, PyAny>, b: &Bound<'py, PyAny>) -> PyResult<Self> {
        let py = a.py();
        let np = py.import("numpy")?;
        let float64 = np.getattr("float64")?;
        let a = np.call_method1("asarray", (a, &float64))?;
        let b = np.call_method1("asarray", (b, &float64))?;
        let scalar = a.getattr("ndim")?.extract::<usize>()? == 0 && b.getattr("ndim")?.extract::<usize>()? == 0;
        let both = np.call_method1("broadcast_arrays", (a, b))?;
        // Contiguous and aligned (a copy where it is not: broadcast views, slices with a
        // step, arrays in byte buffers received from other processes).
        let contiguous = |i: usize| -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
            let array = np.call_method1("require", (both.get_item(i)?, &float64, "CA"))?;
            Ok(array.cast_into::<PyArrayDyn<f64>>()?.readonly())
        };
        let (a, b) = (contiguous(0)?, contiguous(1)?);
        let shape = a.shape().to_vec();
        Ok(Pair { a, b, shape, scalar })
    }

    /// The two inputs as slices of the same length.
    pub(crate) fn slices(&self) -> PyResult<(&[f64], &[f64])> {
        Ok((self.a.as_slice()?, self.b.as_slice()?))
    }

    /// The results: floats for scalar inputs, else arrays of the inputs' shape; one
    /// value or array alone, several as a tuple.
    pub(crate) fn results(&self, py: Python<'py>, outputs: Vec<Vec<f64>>) -> PyResult<Bound<'py, PyAny>> {
        let mut items: Vec<Bound<'py, PyAny>> = Vec::with_capacity(outputs.len());
        for values in outputs {
            if self.scalar {
                items.push(values[0].into_pyobject(py)?.into_any());
            } else {
                let array = numpy::PyArray1::from_vec(py, values).reshape(self.shape.clone())?;
                items.push(array.into_any());
            }
        }
        if items.len() == 1 {
            Ok(items.remove(0))
        } else {
            Ok(PyTuple::new(py, items)?.into_any())
        }
    }
}
