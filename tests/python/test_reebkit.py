"""The Python module against the command line: the same graphs, the same
errors, the same collection; evaluate against hand-computed measures."""
import concurrent.futures
import json
import math
import shutil
import threading
import time
import warnings

import numpy as np
import pytest

import reebkit
from conftest import DATASETS

MESHES = ["elk.off", "eight.off", "cow.off", "hand.off"]


def read_ply_vertices(path):
    """The vertex element of a binary little-endian PLY written by reebkit, as a numpy record array."""
    types = {"double": "<f8", "float": "<f4", "uchar": "u1", "int": "<i4"}
    with open(path, "rb") as f:
        fields, count, in_vertex = [], 0, False
        while (line := f.readline().decode().split()) != ["end_header"]:
            if line[0] == "element":
                in_vertex, count = line[1] == "vertex", count if line[1] != "vertex" else int(line[2])
            elif line[0] == "property" and in_vertex:
                fields.append((line[2], types[line[1]]))
        return np.frombuffer(f.read(count * np.dtype(fields).itemsize), dtype=fields)


@pytest.mark.parametrize("mesh", MESHES)
def test_reeb_graph_equals_the_cli_json(mesh, reeb, tmp_path):
    reeb("graph", DATASETS / mesh, "-o", tmp_path / "g.json", "--ply", tmp_path / "s.ply")
    cli = json.loads((tmp_path / "g.json").read_text())
    V, F = reebkit.load_mesh(DATASETS / mesh)
    assert (len(V), len(F)) == (cli["vertices"], cli["triangles"])  # the file's numbering
    g = reebkit.reeb_graph(V, F)

    assert g.num_nodes == len(cli["nodes"]) and len(g.edges) == len(cli["edges"])
    assert g.edges.tolist() == cli["edges"]
    assert g.feature_points.tolist() == cli["feature_points"]
    assert (g.cycles, g.leaves) == (cli["cycles"], cli["leaves"])
    for key in ("birth_vertex", "vertex_count", "area", "fq_min", "fq_max"):
        assert g.nodes[key].tolist() == [n[key] for n in cli["nodes"]], key
    assert [reebkit.NODE_TYPES[t] for t in g.nodes["type"]] == [n["type"] for n in cli["nodes"]]
    assert [reebkit.NODE_TYPES[t] for t in g.nodes["end"]] == [n["end"] for n in cli["nodes"]]
    assert g.nodes["barycenter"].tolist() == [n["barycenter"] for n in cli["nodes"]]
    assert g.node_attributes.tolist() == [[n["attributes"][a] for a in reebkit.NODE_ATTRIBUTES] for n in cli["nodes"]]
    assert [s.tolist() for s in g.skeleton] == cli["skeleton"]
    assert g.signature.tolist() == cli["signature"][0]

    ply = read_ply_vertices(tmp_path / "s.ply")
    assert g.vertex_node.tolist() == ply["node"].astype(int).tolist()
    assert g.fq.tolist() == ply["fq"].tolist()


def test_features_and_quotient_function_equal_the_cli(reeb, tmp_path):
    mesh = DATASETS / "cow.off"
    reeb("features", mesh, "-o", tmp_path / "f.json", "--epsilon", "0.1", "--geodesic", "fmm")
    cli = json.loads((tmp_path / "f.json").read_text())["components"][0]
    V, F = reebkit.load_mesh(mesh)
    assert reebkit.features(V, F, epsilon=0.1, geodesic="fmm").tolist() == [p["vertex"] for p in cli["feature_points"]]
    fq = reebkit.quotient_function(V, F)
    assert fq.shape == (len(V),) and fq.min() == 0.0 and fq.max() == 1.0
    assert np.all(fq[reebkit.features(V, F)] == 1.0)


def test_defaults_are_the_librarys():
    assert reebkit.analysis_options()["epsilon"] == 0.15
    assert reebkit.analysis_options()["geodesic"] == "fmm"
    for name, value in reebkit.analysis_options().items():
        assert f"{name}={value!r}" in reebkit.features.__doc__ or f"{name}={value}" in reebkit.features.__doc__
    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    explicit = reebkit.reeb_graph(V, F, **reebkit.analysis_options())
    assert explicit.edges.tolist() == reebkit.reeb_graph(V, F).edges.tolist()


def test_geodesic_distance():
    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    d = reebkit.geodesic_distance(V, F, 0)
    assert d.shape == (len(V),) and d[0] == 0.0 and np.all(np.isfinite(d))
    edge = np.linalg.norm(V[F[:, 0]] - V[F[:, 1]], axis=1)
    assert np.all(np.abs(d[F[:, 0]] - d[F[:, 1]]) <= edge + 1e-9)  # 1-Lipschitz along edges
    fmm = reebkit.geodesic_distance(V, F, [0, 10], method="fmm")
    assert fmm[0] == fmm[10] == 0.0 and np.all(fmm <= reebkit.geodesic_distance(V, F, [0, 10]) + 1e-9)


def test_arrays_are_views_not_copies():
    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    assert not V.flags.owndata and not F.flags.owndata  # owned by the moved C++ buffers
    g = reebkit.reeb_graph(V, F)
    assert g.edges.base is not None and not g.edges.flags.writeable
    assert np.may_share_memory(g.nodes["area"], g.nodes["barycenter"])  # columns of one C++ table


def test_arrays_are_numbered_as_the_rows_of_V():
    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    # An unused vertex first and a small second component: left out by cleaning, as from a file.
    far = V.max(axis=0) + 10
    V2 = np.vstack([[0.0, 0.0, 0.0], V, far, far + [1, 0, 0], far + [0, 1, 0]])
    F2 = np.vstack([F + 1, [len(V) + 1, len(V) + 2, len(V) + 3]])
    with pytest.warns(RuntimeWarning, match="component"):
        g = reebkit.reeb_graph(V2, F2)
    reference = reebkit.reeb_graph(V, F)
    assert g.feature_points.tolist() == (reference.feature_points + 1).tolist()
    assert g.vertex_node[0] == -1 and g.vertex_node[1:-3].tolist() == reference.vertex_node.tolist()
    assert np.isnan(g.fq[-1]) and g.fq[1:-3].tolist() == reference.fq.tolist()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(reebkit.InvalidArgument, match="vertex 0 is not on the analysed surface"):
            reebkit.geodesic_distance(V2, F2, 0)


def test_bad_input_raises_with_the_file_named(reeb, tmp_path):
    missing = tmp_path / "missing.off"
    with pytest.raises(reebkit.MeshFileError, match=str(missing)):
        reebkit.load_mesh(missing)
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n4 2 0\n0 0 0\n1 0 0\n")
    with pytest.raises(reebkit.MeshFileError) as error:
        reebkit.load_mesh(bad)
    cli = reeb("graph", bad, "-o", tmp_path / "g.json", check=False)
    assert cli.returncode == 1
    assert cli.stderr.strip() == f"reeb graph: error: {error.value}"  # the same message
    assert str(bad) in str(error.value)

    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    with pytest.raises(reebkit.InvalidMeshError, match=r"\(V, F\)"):
        reebkit.reeb_graph(V, F + len(V))
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        reebkit.reeb_graph(V[:, :2], F)
    with pytest.raises(reebkit.InvalidArgument, match="geodesic"):
        reebkit.features(V, F, geodesic="euclid")
    with pytest.raises(ValueError):  # InvalidArgument is a ValueError too
        reebkit.features(V, F, epsilon="x")
    with pytest.raises(TypeError, match="unknown analysis option 'epsilom'"):
        reebkit.features(V, F, epsilom=0.1)
    with pytest.raises(reebkit.Error, match="no-such.h5"):
        reebkit.Collection(tmp_path / "no-such.h5")


def test_match_equals_reeb_match(reeb):
    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    W, G = reebkit.load_mesh(DATASETS / "cow.off")
    a, b = reebkit.reeb_graph(V, F), reebkit.reeb_graph(W, G)
    distance, correspondence = reebkit.match(a, b)
    cli = reeb("match", DATASETS / "elk.off", DATASETS / "cow.off").stdout
    assert cli.splitlines()[0] == f"distance {distance:.6g}"
    assert correspondence.shape == (a.num_nodes,) and correspondence.max() < b.num_nodes
    assert reebkit.match(a, a)[0] == 0.0
    heavy = reebkit.MatchingOptions()
    heavy.unmatched_cost = 2 * heavy.unmatched_cost
    assert reebkit.match(a, b, heavy)[0] != distance


def test_collection_reads_back(collection, reeb):
    c = reebkit.Collection(collection)
    files = sorted(p.name for p in DATASETS.glob("*.off"))
    assert len(c) == len(files) and sorted(c.names) == files
    assert c.signatures.shape == (len(c), len(reebkit.SIGNATURE))
    assert c.analysis_options == reebkit.analysis_options()
    for name in c.names:
        exported = json.loads(reeb("export", collection, name, "--json").stdout)
        g = c[name]
        assert g.name == name and g.ok and g.vertex_node is None
        assert g.edges.tolist() == exported["edges"]
        assert g.feature_points.tolist() == exported["feature_points"]
        assert g.num_nodes == len(exported["nodes"])
        V, F = reebkit.load_mesh(DATASETS / name)
        fresh = reebkit.reeb_graph(V, F)
        assert fresh.signature.tolist() == g.signature.tolist()
        assert reebkit.match(fresh, g)[0] == 0.0
    assert c[-1].name == c.names[-1] and [g.name for g in c.graphs()] == c.names
    with pytest.raises(KeyError):
        c["no-such-mesh"]
    with pytest.raises(IndexError):
        c[len(c)]


def same_collections(a, b):
    """Two collection files hold the same entries: names, statuses, signatures, graphs."""
    a, b = reebkit.Collection(a), reebkit.Collection(b)
    assert a.names == b.names and a.analysis_options == b.analysis_options
    assert np.array_equal(a.signatures, b.signatures, equal_nan=True)
    for ga, gb in zip(a.graphs(), b.graphs()):
        assert ga.ok == gb.ok and ga.edges.tolist() == gb.edges.tolist()
        assert np.array_equal(ga.node_attributes, gb.node_attributes)


def test_index_equals_reeb_index(collection, tmp_path):
    path = tmp_path / "py.h5"
    summary = reebkit.index(DATASETS, path, threads=1)
    files = sorted(p.name for p in DATASETS.glob("*.off"))
    assert summary["file"] == str(path) and summary["ok"] == len(files)
    assert summary["failed"] == [] and summary["skipped"] == 0 and summary["kept"] == 0
    same_collections(path, collection)
    assert (tmp_path / "py.query.h5").exists()  # as `reeb index` writes it
    again = reebkit.index([DATASETS], path, resume=True)
    assert again["ok"] == 0 and again["skipped"] == len(files)
    with pytest.raises(ValueError, match="epsilon"):
        reebkit.index(DATASETS, tmp_path / "bad.h5", epsilon=5)
    (tmp_path / "broken").mkdir()
    (tmp_path / "broken" / "bad.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(reebkit.Error, match="every mesh failed .1., the first: bad.off"):
        reebkit.index(tmp_path / "broken", tmp_path / "none.h5")
    assert not (tmp_path / "none.h5").exists()


def test_index_stops_on_ctrl_c_keeps_every_entry_and_resume_completes(collection, tmp_path):
    import os
    import signal

    states = []

    def interrupt_after_two(state):
        states.append(state)
        if state["ok"] + state["failed"] == 2:
            os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C

    path = tmp_path / "c.h5"
    with pytest.raises(KeyboardInterrupt, match="c.h5.partial holds"):
        reebkit.index(DATASETS, path, threads=2, progress=interrupt_after_two)
    assert states[0]["total"] == len(list(DATASETS.glob("*.off"))) and states[0]["seconds"] >= 0
    assert not path.exists()
    kept = len(reebkit.Collection(tmp_path / "c.h5.partial"))
    assert 2 <= kept < states[0]["total"]
    resumed = reebkit.index(DATASETS, path, threads=2, resume=True)
    assert resumed["skipped"] == kept and resumed["ok"] == states[0]["total"] - kept
    same_collections(path, collection)

    # An exception of the callable stops the run the same way, and is raised as it is.
    def fail(state):
        raise ValueError("stop here")

    with pytest.raises(ValueError, match="stop here"):
        reebkit.index(DATASETS, tmp_path / "d.h5", progress=fail)
    assert len(reebkit.Collection(tmp_path / "d.h5.partial")) >= 1


def test_graph_stability_equals_reeb_info(reeb, tmp_path):
    """Per class, the graphs with the class's most common (feature points, nodes,
    cycles), as `reeb info` prints them: a copy of the elk has the elk's graph,
    the cow (genus 0) not the elk's (genus 1)."""
    folder = tmp_path / "meshes"
    folder.mkdir()
    for name in ("elk", "cow", "eight"):
        shutil.copy(DATASETS / f"{name}.off", folder / f"{name}.off")
    shutil.copy(DATASETS / "elk.off", folder / "elk_copy.off")
    (tmp_path / "k.cla").write_text("PSB 1\n2 4\n\nanimal 0 3\nelk\nelk_copy\ncow\n\nshape 0 1\neight\n")
    reeb("index", folder, "-o", tmp_path / "c.h5", "--classes", tmp_path / "k.cla", "--threads", "1")
    s = reebkit.Collection(tmp_path / "c.h5").graph_stability()
    assert [k["class"] for k in s["classes"]] == ["animal", "shape"]
    animal = s["classes"][0]
    assert (animal["members"], animal["agreeing"], animal["most_common"][2]) == (3, 2, 1)
    assert (s["members"], s["agreeing"], s["share"]) == (4, 3, 0.75)
    printed = reeb("info", tmp_path / "c.h5").stdout
    for k in s["classes"]:
        f, n, c = k["most_common"]
        assert f"  {k['class']}\t{k['members']}\t{k['agreeing']} with {f} / {n} / {c}\n" in printed


def test_query_equals_reeb_query(collection, reeb):
    c = reebkit.Collection(collection)
    mesh = DATASETS / "elk.off"
    cli = json.loads(reeb("query", collection, mesh, "-k", "5", "--json").stdout)["results"]
    for query in (mesh, str(mesh), reebkit.load_mesh(mesh), reebkit.reeb_graph(*reebkit.load_mesh(mesh)), "elk.off"):
        results = c.query(query, k=5)
        assert [r["name"] for r in results] == [r["name"] for r in cli]
        assert [r["distance"] for r in results] == pytest.approx([r["distance"] for r in cli], rel=1e-5)
    assert c.query(mesh, k=1)[0]["distance"] == 0.0


def test_query_reads_the_query_file_or_the_whole_collection_alike(collection, tmp_path):
    # reeb index wrote datasets.query.h5 beside the collection; a copy without it is read whole.
    assert collection.with_suffix(".query.h5").exists()
    alone = tmp_path / "alone.h5"
    alone.write_bytes(collection.read_bytes())
    mesh = reebkit.load_mesh(DATASETS / "elk.off")
    with_file = reebkit.Collection(collection).query(mesh, k=8, candidates=5)
    whole = reebkit.Collection(alone).query(mesh, k=8, candidates=5)
    assert with_file == whole


def test_distances_equal_reeb_distances(collection, reeb, tmp_path):
    c = reebkit.Collection(collection)
    d = c.distances(threads=1)
    reeb("distances", collection, "-o", tmp_path / "d.matrix")
    cli = np.fromfile(tmp_path / "d.matrix", dtype="<f4").reshape(len(c), len(c))
    assert np.array_equal(d.astype(np.float32), cli)
    assert np.array_equal(d, d.T) and np.all(np.diag(d) == 0)
    assert np.array_equal(c.distances(threads=2), d)


def test_distances_warn_of_failed_entries_as_the_cli(reeb, tmp_path):
    # Before: the CLI warned, Python said nothing.
    folder = tmp_path / "meshes"
    folder.mkdir()
    (folder / "eight.off").write_bytes((DATASETS / "eight.off").read_bytes())
    (folder / "bad.off").write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n")
    reeb("index", folder, "-o", tmp_path / "c.h5", "--allow-failures")
    cli = reeb("distances", tmp_path / "c.h5", "-o", tmp_path / "d.matrix").stderr
    with pytest.warns(RuntimeWarning) as caught:
        reebkit.Collection(tmp_path / "c.h5").distances(threads=1)
    message = str(caught[0].message)
    assert message.startswith("1 of 2 entries failed when indexed") and "bad.off" in message
    assert f"warning: {message}" in cli


def test_query_refuses_a_graph_analysed_with_other_options(collection):
    # Before: a wrong distance (0.496 for the mesh itself), silently.
    c = reebkit.Collection(collection)
    V, F = reebkit.load_mesh(DATASETS / "elk.off")
    other = dict(c.analysis_options, epsilon=c.analysis_options["epsilon"] / 2)
    with pytest.raises(ValueError, match="epsilon"):
        c.query(reebkit.reeb_graph(V, F, **other))
    assert c.query(reebkit.reeb_graph(V, F, **c.analysis_options), k=1)[0]["distance"] == 0.0
    assert c.query(c["elk.off"], k=1)[0]["distance"] == 0.0


def test_out_of_range_options_are_refused():
    # Before: Python skipped even the analysis options' checks.
    V, F = reebkit.load_mesh(DATASETS / "eight.off")
    with pytest.raises(ValueError, match="epsilon"):
        reebkit.reeb_graph(V, F, epsilon=5.0)
    for name, bad in (("structure_weight", -100.0), ("unmatched_cost", -5.0), ("attribute_weight", float("nan"))):
        options = reebkit.MatchingOptions()
        with pytest.raises(ValueError, match=name):
            setattr(options, name, bad)
        with pytest.raises(ValueError, match=name):
            reebkit.MatchingOptions(**{name: bad})
        assert getattr(options, name) == getattr(reebkit.MatchingOptions(), name)
    with pytest.raises(TypeError, match="no_such_weight"):
        reebkit.MatchingOptions(no_such_weight=1.0)


def test_evaluate_on_a_hand_made_matrix():
    # Six models on a line, classes A = {0, 1, 2} at 0, 2, 4 and B = {3, 4, 5}
    # at 1, 10, 11. Rankings (ties by index): q0: 3 1 2 4 5; q1: 3 0 2 4 5;
    # q2: 1 3 0 4 5; q3: 0 1 2 4 5; q4: 5 2 1 3 0; q5: 4 2 1 3 0.
    x = np.array([0, 2, 4, 1, 10, 11], dtype=float)
    matrix = np.abs(x[:, None] - x[None, :])
    labels = ["A", "A", "A", "B", "B", "B"]
    result = reebkit.evaluate(matrix, labels)
    log2 = math.log2
    dcg_a = (1 + 1 / log2(3)) / 2  # q0, q1: members at ranks 2, 3; q2: at 1, 3
    dcg = [dcg_a, dcg_a, dcg_a, (1 / log2(4) + 1 / log2(5)) / 2, 0.75, 0.75]
    assert result["queries"] == 6
    assert result["NN"] == pytest.approx(3 / 6)
    assert result["FT"] == pytest.approx((0.5 * 5 + 0) / 6)
    assert result["ST"] == pytest.approx((5 + 0.5) / 6)
    assert result["E"] == pytest.approx(4 / 7)  # r = 2 of K = 2 in the first m = 5: 2r / (m + K)
    assert result["DCG"] == pytest.approx(sum(dcg) / 6)
    assert result["macro"]["NN"] == pytest.approx((1 / 3 + 2 / 3) / 2)
    assert result["classes"]["B"]["FT"] == pytest.approx(1 / 3)
    assert result["classes"]["A"]["size"] == 3 and len(result["recall"]) == 20


def test_evaluate_with_a_cla_file(tmp_path):
    (tmp_path / "c.cla").write_text("PSB 1\n2 6\n\nA 0 3\na0\na1\na2\n\nB 0 3\nb0\nb1\nb2\n")
    x = np.array([0, 2, 4, 1, 10, 11], dtype=float)
    matrix = np.abs(x[:, None] - x[None, :])
    assert reebkit.evaluate(matrix, tmp_path / "c.cla") == reebkit.evaluate(matrix, list("AAABBB"))
    with pytest.raises(reebkit.InvalidArgument, match="6 x 6"):
        reebkit.evaluate(matrix, list("AAABB"))


def test_to_networkx():
    networkx = pytest.importorskip("networkx")
    V, F = reebkit.load_mesh(DATASETS / "eight.off")
    g = reebkit.reeb_graph(V, F)
    n = g.to_networkx()
    assert isinstance(n, networkx.Graph) and n.number_of_nodes() == g.num_nodes
    assert sorted(map(tuple, n.edges)) == [tuple(e) for e in g.edges.tolist()]
    assert n.nodes[0]["type"] == "root"
    assert networkx.number_connected_components(n) == 1 and g.cycles == 2


def torus(major, minor):
    """A torus of major x minor vertices (genus 1) as V, F."""
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, major, endpoint=False),
                       np.linspace(0, 2 * np.pi, minor, endpoint=False), indexing="ij")
    V = np.stack([(1 + 0.35 * np.cos(v)) * np.cos(u), (1 + 0.35 * np.cos(v)) * np.sin(u), 0.35 * np.sin(v)], axis=-1)
    i, j = np.meshgrid(np.arange(major), np.arange(minor), indexing="ij")
    a, b = i * minor + j, ((i + 1) % major) * minor + j
    c, d = ((i + 1) % major) * minor + (j + 1) % minor, i * minor + (j + 1) % minor
    F = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    return V.reshape(-1, 3), F.astype(np.int32)


def test_the_gil_is_released_during_a_call():
    V, F = torus(200, 100)
    assert reebkit.reeb_graph(V, F).cycles == 1
    done, span = threading.Event(), []

    def work():
        start = time.perf_counter()
        reebkit.reeb_graph(V, F)
        span.append(time.perf_counter() - start)
        done.set()

    worker = threading.Thread(target=work)
    ticks = [time.perf_counter()]
    worker.start()
    while not done.is_set():  # this thread runs on while the call computes
        ticks.append(time.perf_counter())
    worker.join()
    assert max(np.diff(ticks)) < span[0] / 2, (max(np.diff(ticks)), span[0])


def test_threads_give_the_serial_results():
    meshes = [reebkit.load_mesh(DATASETS / m) for m in MESHES]
    serial = [reebkit.reeb_graph(V, F).edges.tolist() for V, F in meshes]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        parallel = list(pool.map(lambda vf: reebkit.reeb_graph(*vf).edges.tolist(), meshes))
    assert parallel == serial
