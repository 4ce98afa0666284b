using AcDream.Core.Dat;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.Streaming;

/// <summary>
/// One landblock as the background loader hands it to the frame loop: the outdoor heights, the
/// indoor cells, and the environments whose cell shapes those cells use. Nothing here is turned into
/// physics yet; <see cref="GameWindow"/> does that on the frame thread.
/// </summary>
/// <param name="LandBlock">The landblock (<c>0xXXYYFFFF</c>): its 9 × 9 height indices.</param>
/// <param name="EnvCells">Its indoor cells (<c>0xXXYYCCCC</c>, CCCC 0x0100..0xFFFD); may be empty.</param>
/// <param name="Environments">
/// The environments the cells use, by full id (<c>0x0D000000 | EnvCell.EnvironmentId</c>); each
/// holds the <see cref="CellStruct"/>s a cell picks with <see cref="EnvCell.CellStructure"/>.
/// </param>
public sealed record LoadedLandblock(
    LandBlock LandBlock,
    IReadOnlyList<EnvCell> EnvCells,
    IReadOnlyDictionary<uint, Environment> Environments);
