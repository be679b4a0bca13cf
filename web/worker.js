// The engine's thread: the page posts a file to read, points to reconstruct, or a download
// to write; the answers carry the request's id. The last reconstruction is kept for the
// downloads.
import init, { parsePoints, reconstruct } from './pkg/wdm_crust_web.js';

const ready = init();
let last = null;

function reply(message, transfer = []) {
  self.postMessage(message, transfer);
}

function drawing(outcome) {
  return {
    curveClosed: outcome.curveClosed(),
    curveOffsets: outcome.curveOffsets(),
    curvePoints: outcome.curvePoints(),
    curveCoords: outcome.curveCoords(),
    unassigned: outcome.unassigned(),
    axisVertices: outcome.axisVertices(),
    axisEdges: outcome.axisEdges(),
    delaunayEdges: outcome.delaunayEdges(),
    voronoiVertices: outcome.voronoiVertices(),
    voronoiEdges: outcome.voronoiEdges(),
    voronoiRays: outcome.voronoiRays(),
    voronoiBisectors: outcome.voronoiBisectors(),
    labels: outcome.labels(),
    warningPoints: outcome.warningPoints(),
  };
}

function handle(request) {
  const { id } = request;
  switch (request.type) {
    case 'parse': {
      const coords = parsePoints(request.name, new Uint8Array(request.bytes));
      reply({ type: 'points', id, coords }, [coords.buffer]);
      break;
    }
    case 'run': {
      const { coords, choices } = request;
      const start = performance.now();
      let lap = start;
      const outcome = reconstruct(
        coords, choices.algorithm, choices.peeling, choices.medialAxis, choices.smooth,
        choices.thinning, choices.voronoi,
        (phase) => {
          const now = performance.now();
          reply({ type: 'progress', id, phase, ms: now - lap });
          lap = now;
        },
      );
      const ms = performance.now() - start;
      if (last) last.free();
      last = outcome;
      const d = drawing(outcome);
      const transfer = Object.values(d).map((array) => array.buffer);
      reply({
        type: 'result', id, ms, drawing: d,
        summary: outcome.summary(), warnings: outcome.warnings(),
      }, transfer);
      break;
    }
    case 'export': {
      if (!last) throw new Error('nothing reconstructed yet');
      const { format, layers } = request;
      const text = format === 'svg'
        ? last.svg(layers.delaunay, layers.voronoi, layers.labels, layers.yDown)
        : format === 'geojson' ? last.geojson() : last.json();
      reply({ type: 'file', id, text });
      break;
    }
    default:
      throw new Error(`unknown request ${request.type}`);
  }
}

self.onmessage = async ({ data }) => {
  try {
    await ready;
    handle(data);
  } catch (e) {
    reply({ type: 'error', id: data.id, message: e instanceof Error ? e.message : String(e) });
  }
};

ready.then(
  () => reply({ type: 'ready' }),
  (e) => reply({ type: 'error', id: null, message: `the engine did not load: ${e}` }),
);
