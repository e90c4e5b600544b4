//! Python inputs to slices and results back: coordinates given as scalars or
//! array-likes of any shape are broadcast together and read as contiguous, aligned float64; the
//! results take their shape, or are Python floats when every input was a scalar.

use numpy::{PyArrayDyn, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

/// `N` broadcast coordinate arrays, borrowed for reading.
pub(crate) struct Points<'py, const N: usize> {
    arrays: [PyReadonlyArrayDyn<'py, f64>; N],
    shape: Vec<usize>,
    scalar: bool,
}

impl<'py, const N: usize> Points<'py, N> {
    /// Reads `N` coordinates (numbers, sequences or arrays of any numeric type).
    pub(crate) fn new(inputs: [&Bound<'py, PyAny>; N]) -> PyResult<Self> {
        let py = inputs[0].py();
        let np = py.import("numpy")?;
        let float64 = np.getattr("float64")?;
        let mut arrays = Vec::with_capacity(N);
        let mut scalar = true;
        for input in inputs {
            let array = np.call_method1("asarray", (input, &float64))?;
            scalar &= array.getattr("ndim")?.extract::<usize>()? == 0;
            arrays.push(array);
        }
        let all = np.call_method1("broadcast_arrays", PyTuple::new(py, arrays)?)?;
        // Contiguous and aligned (a copy where it is not: broadcast views, slices with a
        // step, arrays in byte buffers received from other processes).
        let contiguous = |i: usize| -> PyResult<PyReadonlyArrayDyn<'py, f64>> {
            let array = np.call_method1("require", (all.get_item(i)?, &float64, "CA"))?;
            Ok(array.cast_into::<PyArrayDyn<f64>>()?.readonly())
        };
        let arrays: Vec<_> = (0..N).map(contiguous).collect::<PyResult<_>>()?;
        let arrays: [PyReadonlyArrayDyn<'py, f64>; N] =
            arrays.try_into().unwrap_or_else(|_| unreachable!("N arrays were made"));
        let shape = arrays[0].shape().to_vec();
        Ok(Points { arrays, shape, scalar })
    }

    /// Whether every input was a scalar.
    pub(crate) fn is_scalar(&self) -> bool {
        self.scalar
    }

    /// The broadcast shape.
    pub(crate) fn shape(&self) -> &[usize] {
        &self.shape
    }

    /// The inputs as slices of the same length.
    pub(crate) fn slices(&self) -> PyResult<[&[f64]; N]> {
        let mut out = [&[][..]; N];
        for (slot, array) in out.iter_mut().zip(&self.arrays) {
            *slot = array.as_slice()?;
        }
        Ok(out)
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
