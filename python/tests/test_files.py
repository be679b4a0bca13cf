"""`wdm_crust.read_points`: the command line's parser and its messages. The agreement on
every real file is in test_geojson (the same triangulation as `wdm-crust triangulate FILE`);
here the formats, the columns and the errors."""

import subprocess

import numpy as np
import pytest

import wdm_crust
from .conftest import CLI


def cli_error(path, *args):
    """The command line's one-line message for reading `path`, without its prefix."""
    done = subprocess.run(
        [str(CLI), "triangulate", str(path), *args], capture_output=True, check=False
    )
    assert done.returncode != 0
    message = done.stderr.decode().strip()
    assert message.startswith("wdm-crust: "), message
    return message[len("wdm-crust: ") :]


def test_formats(tmp_path):
    text = tmp_path / "points.txt"
    text.write_text("# x y z\n1.5 2 0.1\r\n-3,4e2,0.2\r5\t6\t0.8\n\n")
    assert wdm_crust.read_points(text).tolist() == [[1.5, 2.0], [-3.0, 400.0], [5.0, 6.0]]
    csv = tmp_path / "points.csv"
    csv.write_text("id,lon,lat\n7,1.5,2\n8,-3,400\n")
    assert wdm_crust.read_points(str(csv)).tolist() == [[1.5, 2.0], [-3.0, 400.0]]
    node = tmp_path / "points.node"
    node.write_text("3 2 0 0\n0 1 2\n1 3 4\n2 5 6\n")
    points = wdm_crust.read_points(node)
    assert points.dtype == np.float64 and points.shape == (3, 2)
    assert points.tolist() == [[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]
    empty = tmp_path / "empty.txt"
    empty.write_text("# nothing\n")
    assert wdm_crust.read_points(empty).shape == (0, 2)


def test_columns(tmp_path, cli):
    csv = tmp_path / "scan.csv"
    csv.write_text("t,east_m,north_m,h\n0,1,2,9\n1,3,5,9\n2,7,1,9\n")
    by_name = wdm_crust.read_points(csv, columns="east_m,north_m")
    assert by_name.tolist() == [[1.0, 2.0], [3.0, 5.0], [7.0, 1.0]]
    assert wdm_crust.read_points(csv, columns=("east_m", "north_m")).tolist() == by_name.tolist()
    assert wdm_crust.read_points(csv, columns=(2, 3)).tolist() == by_name.tolist()
    assert wdm_crust.read_points(csv, columns="4,2").tolist() == [[9.0, 1.0], [9.0, 3.0], [9.0, 7.0]]
    with pytest.raises(ValueError) as error:
        wdm_crust.read_points(csv, columns="east,north")
    assert str(error.value) == cli_error(csv, "--columns", "east,north")
    with pytest.raises(ValueError, match="two columns"):
        wdm_crust.read_points(csv, columns=("a", "b", "c"))
    # Without --columns the header has no coordinate pair: refused, as on the command line.
    with pytest.raises(ValueError) as error:
        wdm_crust.read_points(csv)
    assert str(error.value) == cli_error(csv)


@pytest.mark.parametrize(
    "name,content",
    [
        ("word.txt", "1 2\n3 four\n"),
        ("decimal_comma.txt", "0,5 1,5\n"),
        ("nan.txt", "1 2\nnan 3\n"),
        ("one_column.txt", "1 2\n3\n"),
        ("bad.node", "2 2 0 0\n0 1 2\n"),
        ("binary.txt", "\x89PNG\r\n\x1a\n\x00\x00"),
    ],
)
def test_errors_are_the_cli_messages(tmp_path, name, content):
    path = tmp_path / name
    path.write_bytes(content.encode("latin-1"))
    with pytest.raises(ValueError) as error:
        wdm_crust.read_points(path)
    assert str(error.value) == cli_error(path)
    assert str(error.value).startswith(f"{path}:")


def test_files_that_cannot_be_opened(tmp_path):
    missing = tmp_path / "missing.txt"
    with pytest.raises(FileNotFoundError) as error:
        wdm_crust.read_points(missing)
    assert str(error.value) == cli_error(missing)
    with pytest.raises(IsADirectoryError) as error:
        wdm_crust.read_points(tmp_path)
    assert str(error.value) == cli_error(tmp_path)
    with pytest.raises(TypeError):
        wdm_crust.read_points(3)
