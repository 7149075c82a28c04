# Type stubs of sweepcdt (the runtime's docstrings say what each argument means).
import os
from typing import Any, Callable, Iterator, Literal, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from . import errors as errors
from .errors import CancelledError as CancelledError, CheckError as CheckError, Error as Error
from .errors import InvalidInputError as InvalidInputError, NoCdtError as NoCdtError, OutputError as OutputError
from .errors import VertexRemovalError as VertexRemovalError

_Algorithm = Literal["sweep-sphere", "sweep-plane", "giftwrap"]
_Steiner = Literal["auto", "none"]
_Facets = Literal["triangles", "coplanar"]
_Progress = Optional[Callable[[str, int, int], Optional[bool]]]
_Path = Union[str, os.PathLike[str]]

DEFAULTS: dict[str, str]

class TetMesh:
    points: npt.NDArray[np.float64]
    tetrahedra: npt.NDArray[np.int64]
    regions: npt.NDArray[np.int32]
    triangles: npt.NDArray[np.int64]
    triangle_ids: npt.NDArray[np.int64]
    steiner_triangles: npt.NDArray[np.int64]
    point_ids: npt.NDArray[np.int64]
    num_input_points: int
    stats: dict[str, Any]
    @property
    def steiner_points(self) -> npt.NDArray[np.float64]: ...
    def to_meshio(self, boundary: bool = ...) -> Any: ...

class Triangulation:
    dimension: int
    points: npt.NDArray[np.float64]
    simplices: npt.NDArray[np.int64]
    regions: npt.NDArray[np.int32]
    num_input_points: int
    steiner_simplices: npt.NDArray[np.int64]
    stats: dict[str, Any]

class EditedTriangulation(Triangulation):
    constraints: npt.NDArray[np.int64]
    exterior: Optional[npt.NDArray[np.int64]]
    tags: Optional[npt.NDArray[np.int64]]
    old_ids: npt.NDArray[np.int64]
    num_ids: int
    perturbation_rank: Optional[npt.NDArray[np.int64]]
    def to_tet_mesh(self) -> TetMesh: ...

class RemovalReport:
    removed: list[int]
    refused: list[tuple[int, Union[NoCdtError, VertexRemovalError]]]
    @property
    def refused_ids(self) -> list[int]: ...

class EditableCdt:
    def __init__(self, points: npt.ArrayLike, constraints: Optional[npt.ArrayLike] = ..., *,
                 exterior: Optional[npt.ArrayLike] = ..., tags: Optional[npt.ArrayLike] = ...,
                 algorithm: _Algorithm = ..., steiner: _Steiner = ..., facets: _Facets = ...,
                 progress: _Progress = ...) -> None: ...
    @classmethod
    def from_triangulation(cls, points: npt.ArrayLike, simplices: npt.ArrayLike, constraints: npt.ArrayLike, *,
                           exterior: Optional[npt.ArrayLike] = ..., tags: Optional[npt.ArrayLike] = ...,
                           regions: Optional[npt.ArrayLike] = ...) -> EditableCdt: ...
    @classmethod
    def from_tet_mesh(cls, mesh: TetMesh) -> EditableCdt: ...
    @property
    def dimension(self) -> int: ...
    @property
    def num_vertices(self) -> int: ...
    @property
    def num_simplices(self) -> int: ...
    @property
    def vertices(self) -> npt.NDArray[np.int64]: ...
    def has_vertex(self, v: int) -> bool: ...
    def __contains__(self, v: int) -> bool: ...
    def remove_vertex(self, v: int) -> None: ...
    def remove_vertices(self, vertices: npt.ArrayLike, *, progress: _Progress = ...) -> RemovalReport: ...
    def snapshot(self) -> EditedTriangulation: ...
    def plc_without(self, v: int) -> dict[str, Any]: ...

class Surface:
    points: npt.NDArray[np.float64]
    triangles: npt.NDArray[np.int64]
    format: str
    def __iter__(self) -> Iterator[np.ndarray]: ...

def tetrahedralize(points: npt.ArrayLike, triangles: npt.ArrayLike, *, algorithm: _Algorithm = ...,
                   steiner: _Steiner = ..., facets: _Facets = ..., snap: Optional[float] = ..., check: bool = ...,
                   progress: _Progress = ..., name: str = ...) -> TetMesh: ...
def read_surface(path: _Path) -> Surface: ...
def mesh_file(input: _Path, output: Union[_Path, Sequence[_Path]], *, format: Optional[str] = ...,
              algorithm: _Algorithm = ..., steiner: _Steiner = ..., facets: _Facets = ..., snap: Optional[float] = ...,
              check: bool = ..., progress: _Progress = ...) -> TetMesh: ...
def cdt(points: npt.ArrayLike, simplices: npt.ArrayLike, *, exterior: Optional[npt.ArrayLike] = ...,
        tags: Optional[npt.ArrayLike] = ..., algorithm: _Algorithm = ..., steiner: _Steiner = ..., facets: _Facets = ...,
        check: bool = ..., progress: _Progress = ...) -> Triangulation: ...
def read_volume_mesh(path: _Path) -> TetMesh: ...
def write_volume_mesh(path: _Path, mesh: Optional[TetMesh] = ..., *, points: Optional[npt.ArrayLike] = ...,
                      tetrahedra: Optional[npt.ArrayLike] = ..., regions: Optional[npt.ArrayLike] = ...,
                      triangles: Optional[npt.ArrayLike] = ..., triangle_ids: Optional[npt.ArrayLike] = ...,
                      format: Optional[str] = ...) -> None: ...
def check_files(input: _Path, output: _Path, *, facets: _Facets = ..., snap: Optional[float] = ...) -> dict[str, Any]: ...
