// Types of the opencrg npm package (see docs/web.md).

/** Coordinates: one number, or an array of them (`Float64Array` or any array). */
export type Coordinates = number | Float64Array | ArrayLike<number>;
/** An answer per point: a number for numbers given, a `Float64Array` for arrays. */
export type Answer<T extends Coordinates> = T extends number ? number : Float64Array;
/** The second coordinate: a number with a number, an array of the same length with an array. */
export type Like<T extends Coordinates> = T extends number ? number : ArrayLike<number>;
/** Contact point options or modifiers by the file's keywords, in any case. */
export type Settings = Record<string, number>;

export interface LoadOptions {
  /** The behaviour profile: "current" (default) or "2.0.1" for the releases. */
  compat?: string;
  /** Files the road's `$ROAD_CRG_FILE` references are read from, by name. */
  files?: Record<string, Uint8Array>;
}

/** A road: a CRG file in any of the four formats (LRFI, LDFI, KRBI, KDBI). */
export class Road {
  private constructor();
  /** Reads a CRG file held in memory; throws an `Error` with the command's message. */
  static fromBytes(bytes: Uint8Array, name?: string, options?: LoadOptions): Road;
  /** Checks the road as `crgCheck` does; throws when it fails. */
  check(): void;
  /** Applies the modifiers (`crgDataSetModifiersApply`). */
  applyModifiers(): void;
  /** Sets one modifier (`SCALE_Z_GRID`, ...); it acts at the next `applyModifiers()`. */
  setModifier(name: string, value: number): void;
  /** Removes every modifier. */
  clearModifiers(): void;
  readonly uRange: Float64Array;
  readonly vRange: Float64Array;
  readonly increments: Float64Array;
  /** `[uStart, uEnd]` of a closed track, or `null`. */
  readonly closedTrack: Float64Array | null;
  /** `[closed, uStart, uEnd]` as `crgDataSetGetUtilityDataClosedTrack` reports it. */
  readonly closedTrackReport: Float64Array;
  /** The v of the long sections. */
  readonly v: Float64Array;
  /** The elevation grid, cross section after cross section (`u` outer, `v` inner). */
  readonly grid: Float32Array;
  /** comments, road_crg, options, modifiers, mpro, references, format, channels. */
  readonly header: Record<string, unknown>;
  /** The roughness of wheel tracks (`tracks`: their v; default -0.85, 0, 0.85 m), as `opencrg roughness` gives it. */
  roughness(tracks?: Float64Array | number[], segment?: number): Array<{
    v: number;
    iri: number;
    segments: Array<{ uStart: number; uEnd: number; iri: number | null }>;
    /** The displacement PSD: `[n, Gd(n)]` per third-octave band (cycles/m, m³). */
    bands: Array<[number, number]>;
    gdN0: number;
    w: number;
    iso8608: string;
    skipped: number;
  }>;
  /** The 3D view of `opencrg view`: one HTML page. */
  viewPage(name: string, maxVertices?: number): string;
  /** What `opencrg info` says of the road, the file named `name`. */
  info(name: string): string;
  uvToZ<T extends Coordinates>(u: T, v: Like<T>, options?: Settings): Answer<T>;
  xyToZ<T extends Coordinates>(x: T, y: Like<T>, options?: Settings): Answer<T>;
  uvToXy<T extends Coordinates>(u: T, v: Like<T>, options?: Settings): [Answer<T>, Answer<T>];
  xyToUv<T extends Coordinates>(x: T, y: Like<T>, options?: Settings): [Answer<T>, Answer<T>];
  uvToPk<T extends Coordinates>(u: T, v: Like<T>, options?: Settings): [Answer<T>, Answer<T>];
  xyToPk<T extends Coordinates>(x: T, y: Like<T>, options?: Settings): [Answer<T>, Answer<T>];
  /** `[z, nx, ny, nz]`: the elevation and the upward unit normal. */
  uvToNormal<T extends Coordinates>(u: T, v: Like<T>, options?: Settings): [Answer<T>, Answer<T>, Answer<T>, Answer<T>];
  xyToNormal<T extends Coordinates>(x: T, y: Like<T>, options?: Settings): [Answer<T>, Answer<T>, Answer<T>, Answer<T>];
  /** Evaluation `index` of `evaluations()` (what the calls above call). */
  evaluate(index: number, a: Coordinates, b: Coordinates, options?: Settings): number | Float64Array | Array<number | Float64Array>;
  free(): void;
}

/** A point of evaluation: options of its own, an x/y search history. */
export class ContactPoint {
  constructor(road: Road, options?: Settings);
  setOption(name: string, value: number): void;
  readonly options: Settings;
  /** 1 for each point of the last call without an answer: refused (the C API's return code 0) for a number, answered NaN for arrays. */
  readonly refused: Uint8Array;
  uvToZ<T extends Coordinates>(u: T, v: Like<T>): Answer<T>;
  xyToZ<T extends Coordinates>(x: T, y: Like<T>): Answer<T>;
  uvToXy<T extends Coordinates>(u: T, v: Like<T>): [Answer<T>, Answer<T>];
  xyToUv<T extends Coordinates>(x: T, y: Like<T>): [Answer<T>, Answer<T>];
  uvToPk<T extends Coordinates>(u: T, v: Like<T>): [Answer<T>, Answer<T>];
  xyToPk<T extends Coordinates>(x: T, y: Like<T>): [Answer<T>, Answer<T>];
  uvToNormal<T extends Coordinates>(u: T, v: Like<T>): [Answer<T>, Answer<T>, Answer<T>, Answer<T>];
  xyToNormal<T extends Coordinates>(x: T, y: Like<T>): [Answer<T>, Answer<T>, Answer<T>, Answer<T>];
  /** Evaluation `index` of `evaluations()` (what the calls above call). */
  evaluate(index: number, a: Coordinates, b: Coordinates): number | Float64Array | Array<number | Float64Array>;
  free(): void;
}

/** The ground at world points. */
export interface Ground<T extends Coordinates> {
  z: Answer<T>;
  friction: Answer<T>;
  /** The road's index into `roadIds` (-1 off every road). */
  road: Answer<T>;
  lane: Answer<T>;
  s: Answer<T>;
  t: Answer<T>;
}

/** An OpenDRIVE map with the CRG files its records name laid on. */
export class OdrMap {
  private constructor();
  /** Reads a map held in memory with its CRG files (`{name: bytes}`). */
  static fromBytes(bytes: Uint8Array, files?: Record<string, Uint8Array>, name?: string): OdrMap;
  /** The CRG files a map names (each once, as its records write them). */
  static crgFilesOf(bytes: Uint8Array, name?: string): string[];
  ground<T extends Coordinates>(x: T, y: Like<T>): Ground<T>;
  normal<T extends Coordinates>(x: T, y: Like<T>): [Answer<T>, Answer<T>, Answer<T>];
  stToXyz<T extends Coordinates>(road: string, s: T, t: Like<T>): [Answer<T>, Answer<T>, Answer<T>];
  /** The checker's findings (empty when clean). */
  check(): string[];
  /** The 3D view of `opencrg odr view`: one HTML page. */
  viewPage(name: string, maxError?: number): string;
  /** What `opencrg odr info` says. */
  info(): string;
  readonly roadIds: string[];
  readonly roadLengths: Float64Array;
  free(): void;
}

/** The evaluation calls roads and contact points have, in the order `evaluate` takes
 * them: each call's name and the names of the values it takes and gives per point. */
export function evaluations(): Array<{ name: string; inputs: string[]; outputs: string[] }>;

/** OpenDRIVE maps, and the CRG files a map names (to fetch them before reading it). */
export const odr: { Map: typeof OdrMap; crgFilesOf: typeof OdrMap.crgFilesOf };

/** The drawing rules of the command's figures, which the web page follows too. */
export const drawing: {
  /** The colours of values in 0..1 (clamped): red, green, blue bytes for each. */
  elevationColours(t: Float64Array): Uint8Array;
  /** At most `atMost` ticks over [a, b] at the smallest round step (1, 2, 5 x 10^k). */
  ticks(a: number, b: number, atMost: number): Float64Array;
  /** A tick's label: at most six decimals, no trailing zeros. */
  tickLabel(v: number): string;
  /** A power of ten's label: 10 with a superscript exponent (plain from 0.001 to 1000). */
  decadeLabel(v: number): string;
  /** The tracks' colours in turn, and the grey of reference lines, as CSS colours. */
  figureColours(): { tracks: string[]; reference: string };
};

/** The ISO 8608 road classes roughness is classified by: the reference spatial frequency
 * n0 (cycles/m), the limits of Gd(n0) between the classes (m³), the classes' letters. */
export function iso8608Classes(): { n0: number; limits: number[]; classes: string };

/** Base of what the library throws (each an `Error` whose `name` is its class's). */
export class CrgError extends Error {}
/** A file that does not exist (a `$ROAD_CRG_FILE` reference, a map's CRG file). */
export class NotFoundError extends CrgError {}
/** A file that could not be read. */
export class IoError extends CrgError {}
/** A file whose content is wrong; the message names the file, line and field. */
export class FormatError extends CrgError {}
/** A road refused by `check()`. */
export class CheckError extends CrgError {}
/** A request refused before any work: an argument the call does not take. */
export class RequestError extends CrgError {}
/** A request beyond the memory limit. */
export class TooLargeError extends RequestError {}
/** A value the request does not take (an option's choice out of range, a modifier refused). */
export class OutOfRangeError extends RequestError {}
