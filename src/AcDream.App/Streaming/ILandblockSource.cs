namespace AcDream.App.Streaming;

/// <summary>
/// Where the streaming loader gets landblocks from (the dat files in the client; a synthetic world
/// here). Called on the loader thread only, one landblock at a time.
/// </summary>
public interface ILandblockSource
{
    /// <summary>
    /// Reads one landblock with its cells and environments.
    /// </summary>
    /// <param name="landblockId">The landblock, <c>0xXXYYFFFF</c>.</param>
    /// <returns>The landblock; its <c>LandBlock.Id</c> must be <paramref name="landblockId"/>.</returns>
    /// <exception cref="Exception">Any exception means the landblock could not be loaded this time; the window reports it and retries later.</exception>
    LoadedLandblock Load(uint landblockId);
}
